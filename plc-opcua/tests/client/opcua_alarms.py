"""A program's alarms as OPC UA conditions, checked by an independent client (python asyncua).

    opcua_alarms.py check URL SEGMENT PLC PKI WORKDIR USER PASSWORD
    opcua_alarms.py flood URL SEGMENT PLC COUNT
    opcua_alarms.py conditions URL SEGMENT PATH,PATH...

`check`: the program declares `door` (bool, severity 700), `oil` (limits high 80, high_high 95,
severity 600) and `filter` (bool, severity 300), all writable with `plc set`. Checked:
    - each alarm a condition under the program's object (OffNormalAlarmType,
      ExclusiveLimitAlarmType), its variables readable by an anonymous session over None
    - events through an event filter with `Severity >= 600` (an anonymous session over None):
      the raise of `door` with its ConditionId, Time, Message, SourceName, ActiveState/Id,
      AckedState/Id, Retain, and its ActiveState/Id variable's monitored item turns true;
      `oil` above its high limit with LimitState High, through `OfType(LimitAlarmType)` too
      (which `door`'s does not pass); `filter`
      (severity 300) not delivered, while a subscription without the filter gets it
    - Acknowledge by an anonymous session over None: BadUserAccessDenied
    - Acknowledge by the user over SignAndEncrypt with the event's EventId: Good, the event of
      the acknowledgement follows, `plc alarms` shows it acknowledged and its journal names
      the user; again: BadConditionBranchAlreadyAcked; an old EventId: BadEventIdUnknown
    - ConditionRefresh: the calling subscription alone gets the retained conditions
    - `door` back to normal: the event of the return, Retain false
`flood`: the program declares COUNT bool alarms `doors[i]`, all raised and cleared with
`raise_all` (`plc set`): a subscriber (queue of 1,000) gets every one of the COUNT raises,
a ConditionRefresh gives all COUNT between its RefreshStartEvent and RefreshEndEvent, and
every return follows; each in its time (`figure:` lines).
`conditions`: waits (at most 15 s) until the program's object holds exactly the conditions of
the alarms at these paths (after a new declaration), each linked from its variable
(HasCondition) and readable.
Prints one `ok:` line per check and `figure:` lines; exits 1 with `FAILED:` on the first that
fails.
"""

import asyncio
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))

from asyncua import Client, ua  # noqa: E402
from asyncua.crypto import security_policies  # noqa: E402

from opcua_common import Failed, check, figure, ok, plc, user_client  # noqa: E402

FIELDS = ["EventId", "EventType", "SourceName", "Time", "Message", "Severity", "Retain",
          "ActiveState/Id", "AckedState/Id", "LimitState/CurrentState", "ConditionName"]
ACKNOWLEDGE = ua.NodeId(ua.ObjectIds.AcknowledgeableConditionType_Acknowledge)
REFRESH = ua.NodeId(ua.ObjectIds.ConditionType_ConditionRefresh)


def operand(path, attribute=ua.AttributeIds.Value, type_id=ua.ObjectIds.BaseEventType):
    op = ua.SimpleAttributeOperand()
    op.TypeDefinitionId = ua.NodeId(type_id)
    op.BrowsePath = [ua.QualifiedName(n, 0) for n in path.split("/")] if path else []
    op.AttributeId = attribute
    return op


def event_filter(min_severity=None, of_type=None):
    """The fields above and ConditionId; with `min_severity`, `Severity >= min_severity`; with
    `of_type`, `OfType(of_type)`."""
    f = ua.EventFilter()
    f.SelectClauses = [operand(p) for p in FIELDS]
    f.SelectClauses.append(operand("", ua.AttributeIds.NodeId, ua.ObjectIds.ConditionType))
    if min_severity is not None:
        el = ua.ContentFilterElement()
        el.FilterOperator = ua.FilterOperator.GreaterThanOrEqual
        el.FilterOperands = [operand("Severity"),
                             ua.LiteralOperand(Value=ua.Variant(min_severity, ua.VariantType.UInt16))]
        f.WhereClause = ua.ContentFilter()
        f.WhereClause.Elements = [el]
    if of_type is not None:
        el = ua.ContentFilterElement()
        el.FilterOperator = ua.FilterOperator.OfType
        el.FilterOperands = [ua.LiteralOperand(Value=ua.Variant(ua.NodeId(of_type)))]
        f.WhereClause = ua.ContentFilter()
        f.WhereClause.Elements = [el]
    return f


class Events:
    """An event subscription's events, each a dict of the fields and `ConditionId`."""

    def __init__(self):
        self.got = []
        self.arrived = asyncio.Event()

    def event_notification(self, event):
        values = [v.Value for v in event.event_fields]
        fields = dict(zip(FIELDS + ["ConditionId"], values))
        fields["received"] = time.perf_counter()
        self.got.append(fields)
        self.arrived.set()

    async def count(self, n, what, timeout=10):
        """Waits until `n` events have come, then a little longer for any more."""
        deadline = time.monotonic() + timeout
        while len(self.got) < n:
            check(time.monotonic() < deadline, f"{what}: {len(self.got)} events, not {n}")
            await asyncio.sleep(0.01)
        await asyncio.sleep(0.3)

    async def wait(self, what, match, timeout=10):
        deadline = time.monotonic() + timeout
        while True:
            for e in self.got:
                if match(e):
                    return e
            left = deadline - time.monotonic()
            check(left > 0, f"no event {what}; got {[(e['SourceName'], e['ActiveState/Id'], e['AckedState/Id']) for e in self.got]}")
            self.arrived.clear()
            try:
                await asyncio.wait_for(self.arrived.wait(), left)
            except asyncio.TimeoutError:
                pass


class Values:
    """A data change subscription's values."""

    def __init__(self):
        self.got = []

    def datachange_notification(self, node, value, data):
        self.got.append(value)


def of(path, active, acked):
    return lambda e: (e["SourceName"] == path and e["ActiveState/Id"] == active
                      and e["AckedState/Id"] == acked)


async def status_of_call(node, *args):
    try:
        await node.call_method(ACKNOWLEDGE, *args)
        return ua.StatusCodes.Good
    except ua.UaStatusCodeError as e:
        return e.code


async def conditions_readable(client, ns):
    door = client.get_node(ua.NodeId("door#alarm", ns))
    oil = client.get_node(ua.NodeId("oil#alarm", ns))
    program = client.get_node(ua.NodeId(1, ns))
    children = {c.nodeid for c in await program.get_children()}
    check(door.nodeid in children and oil.nodeid in children,
          "the conditions are under the program's object")
    check((await door.read_type_definition()) == ua.NodeId(ua.ObjectIds.OffNormalAlarmType),
          "door is an OffNormalAlarmType")
    check((await oil.read_type_definition()) == ua.NodeId(ua.ObjectIds.ExclusiveLimitAlarmType),
          "oil is an ExclusiveLimitAlarmType")

    async def value(cond, path):
        return await client.get_node(ua.NodeId(f"{cond}#alarm/{path}", ns)).read_value()

    check(await value("door", "ActiveState/Id") is False, "door inactive")
    check(await value("door", "Severity") == 700, "door's severity")
    check((await value("door", "Message")).Text == "Door open", "door's message")
    check(await value("door", "SourceName") == "door", "door's SourceName")
    check(await value("door", "EnabledState/Id") is True, "door enabled")
    check(await value("oil", "HighLimit") == 80.0 and await value("oil", "HighHighLimit") == 95.0,
          "oil's limits")
    check((await value("oil", "ShelvingState/CurrentState")).Text == "Unshelved", "oil unshelved")
    check(await value("oil", "SuppressedState/Id") is False, "oil unsuppressed")
    ok("the conditions and their variables read by an anonymous session over None")


async def sign_and_encrypt_user(url, user, password, pki, workdir):
    # The HMI's certificate made and trusted as `user_client` does, then over SignAndEncrypt.
    await user_client(url, user, password, pki, workdir)
    client = Client(url, timeout=30)
    client.application_uri = "urn:plc-vars:test-hmi"
    client.set_user(user)
    client.set_password(password)
    key, cert = Path(workdir) / "hmi-key.pem", Path(workdir) / "hmi-cert.der"
    await client.set_security(security_policies.SecurityPolicyBasic256Sha256, str(cert), str(key),
                              mode=ua.MessageSecurityMode.SignAndEncrypt)
    return client


async def run(url, segment, plc_bin, pki, workdir, user, password):
    async with Client(url, timeout=30) as client:
        ns = await client.get_namespace_index(f"urn:plc-vars:{segment}")
        await conditions_readable(client, ns)
        severe, every = Events(), Events()
        sub = await client.create_subscription(10, severe)
        await sub.subscribe_events(ua.ObjectIds.Server, evfilter=event_filter(600), queuesize=1000)
        sub_all = await client.create_subscription(10, every)
        every_item = await sub_all.subscribe_events(ua.NodeId(1, ns), evfilter=event_filter(), queuesize=1000)
        limits = Events()
        sub_limits = await client.create_subscription(10, limits)
        await sub_limits.subscribe_events(
            ua.ObjectIds.Server, evfilter=event_filter(of_type=ua.ObjectIds.LimitAlarmType), queuesize=1000)
        values = Values()
        sub_values = await client.create_subscription(10, values)
        await sub_values.subscribe_data_change(client.get_node(ua.NodeId("door#alarm/ActiveState/Id", ns)))
        deadline = time.monotonic() + 10
        while not values.got:  # its first value, before the raise replaces it in the queue
            check(time.monotonic() < deadline, "door's ActiveState/Id monitored: no value")
            await asyncio.sleep(0.01)

        t = time.perf_counter()
        plc(plc_bin, "set", segment, "door=true")
        raised = await severe.wait("of door raised", of("door", True, False))
        check(raised["ConditionId"] == ua.NodeId("door#alarm", ns),
              f"ConditionId {raised['ConditionId']}")
        check(raised["Severity"] == 700 and raised["Message"].Text == "Door open"
              and raised["Retain"] is True and raised["ConditionName"] == "door",
              f"the raise's fields: {raised}")
        check(raised["EventType"] == ua.NodeId(ua.ObjectIds.OffNormalAlarmType), "its type")
        check(abs(raised["Time"].timestamp() - time.time()) < 30, f"its Time {raised['Time']}")
        deadline = time.monotonic() + 10
        while values.got[-1:] != [True]:
            check(time.monotonic() < deadline, f"door's ActiveState/Id monitored: {values.got}")
            await asyncio.sleep(0.01)
        check(values.got[0] is False, f"door's ActiveState/Id monitored: {values.got}")
        ok(f"door raised: its event through `Severity >= 600` with ConditionId (and its "
           f"monitored ActiveState/Id turned true), in "
           f"{(raised['received'] - t) * 1000:.0f} ms from `plc set` (a process) on")

        plc(plc_bin, "set", segment, "oil=85")
        high = await severe.wait("of oil high", of("oil", True, False))
        check(high["LimitState/CurrentState"].Text == "High", f"oil's LimitState {high}")
        check(high["EventType"] == ua.NodeId(ua.ObjectIds.ExclusiveLimitAlarmType), "its type")
        await limits.wait("of oil through OfType(LimitAlarmType)", of("oil", True, False))
        check(all(e["SourceName"] == "oil" for e in limits.got), "OfType(LimitAlarmType) let a bool alarm's event through")
        ok("oil above its high limit: LimitState High, ExclusiveLimitAlarmType; through "
           "`OfType(LimitAlarmType)`, which the door's did not pass")

        plc(plc_bin, "set", segment, "filter=true")
        await every.wait("of filter raised (no filter)", of("filter", True, False))
        await asyncio.sleep(0.5)
        check(not [e for e in severe.got if e["SourceName"] == "filter"],
              "filter (severity 300) passed `Severity >= 600`")
        ok("filter (severity 300): delivered without the filter, not through `Severity >= 600`")

        # ConditionRefresh for the filtered subscription: door and oil again, the other none.
        before, before_all = len(severe.got), len(every.got)
        condition_type = client.get_node(ua.ObjectIds.ConditionType)
        await condition_type.call_method(REFRESH, ua.Variant(sub.subscription_id, ua.VariantType.UInt32))
        await severe.count(before + 2, "ConditionRefresh")
        again = sorted(e["SourceName"] for e in severe.got[before:])
        check(again == ["door", "oil"], f"ConditionRefresh gave {again}")
        check(len(every.got) == before_all, "ConditionRefresh reached another subscription")
        await client.nodes.server.call_method(REFRESH, ua.Variant(sub_all.subscription_id, ua.VariantType.UInt32))
        await every.count(before_all + 5, "ConditionRefresh without a filter")
        types = [e["EventType"] for e in every.got[before_all:]]
        check(types[0] == ua.NodeId(ua.ObjectIds.RefreshStartEventType)
              and types[-1] == ua.NodeId(ua.ObjectIds.RefreshEndEventType) and len(types) == 5,
              f"ConditionRefresh without a filter: {types}")
        # ConditionRefresh2 names the monitored item too: the same five events again.
        before_all = len(every.got)
        refresh2 = ua.NodeId(ua.ObjectIds.ConditionType_ConditionRefresh2)
        await condition_type.call_method(refresh2, ua.Variant(sub_all.subscription_id, ua.VariantType.UInt32),
                                         ua.Variant(every_item, ua.VariantType.UInt32))
        await every.count(before_all + 5, "ConditionRefresh2")
        types = [e["EventType"] for e in every.got[before_all:]]
        check(types[0] == ua.NodeId(ua.ObjectIds.RefreshStartEventType)
              and types[-1] == ua.NodeId(ua.ObjectIds.RefreshEndEventType) and len(types) == 5,
              f"ConditionRefresh2: {types}")
        ok("ConditionRefresh: the calling subscription alone gets the retained conditions "
           "(RefreshStartEvent and RefreshEndEvent around them when its filter lets them); "
           "ConditionRefresh2 the same for one monitored item")

        door = client.get_node(raised["ConditionId"])
        status = await status_of_call(door, ua.Variant(raised["EventId"], ua.VariantType.ByteString),
                                      ua.LocalizedText("anonymous"))
        check(status == ua.StatusCodes.BadUserAccessDenied, f"anonymous over None: {status}")
        ok("Acknowledge by an anonymous session over None: BadUserAccessDenied")

        async with await sign_and_encrypt_user(url, user, password, pki, workdir) as op:
            cond = op.get_node(raised["ConditionId"])
            latest = [e for e in severe.got if e["SourceName"] == "door"][-1]
            status = await status_of_call(cond, ua.Variant(b"not an event", ua.VariantType.ByteString),
                                          ua.LocalizedText("wrong"))
            check(status == ua.StatusCodes.BadEventIdUnknown, f"an unknown EventId: {status}")
            status = await status_of_call(cond, ua.Variant(latest["EventId"], ua.VariantType.ByteString),
                                          ua.LocalizedText("seen from the HMI"))
            check(status == ua.StatusCodes.Good, f"the user's Acknowledge: {status}")
            acked = await severe.wait("of door acknowledged", of("door", True, True))
            shown = plc(plc_bin, "alarms", segment)
            line = [x for x in shown.splitlines() if " door " in f" {x} "]
            check(line and "active acknowledged" in line[0], f"`plc alarms`:\n{shown}")
            # The journal's writer takes the cycle's records every 50 ms: look for up to 5 s.
            deadline = time.monotonic() + 5
            while True:
                history = plc(plc_bin, "alarms", segment, "--history")
                if ("operator" in history and "seen from the HMI" in history) or time.monotonic() > deadline:
                    break
                await asyncio.sleep(0.05)
            check("operator" in history and "seen from the HMI" in history,
                  f"the journal names the user and comment:\n{history}")
            ok("Acknowledge by the user over SignAndEncrypt: Good, its event follows, the "
               "program shows it acknowledged and its journal names the user")
            status = await status_of_call(cond, ua.Variant(acked["EventId"], ua.VariantType.ByteString),
                                          ua.LocalizedText("again"))
            check(status == ua.StatusCodes.BadConditionBranchAlreadyAcked, f"again: {status}")
            ok("Acknowledge of an acknowledged alarm: BadConditionBranchAlreadyAcked")

        plc(plc_bin, "set", segment, "door=false")
        back = await severe.wait("of door back to normal", of("door", False, True))
        check(back["Retain"] is False, f"Retain after the return: {back}")
        ok("door back to normal: its event, Retain false")

        # Raise-to-event latency through `plc set` and the server's 10 ms poll.
        delays = []
        for k in range(20):
            value = "false" if k % 2 == 0 else "true"  # filter is raised now
            n = len(every.got)
            t = time.perf_counter()
            plc(plc_bin, "set", segment, f"filter={value}")
            e = await every.wait("of filter", lambda e, n=n: every.got.index(e) >= n
                                 and e["SourceName"] == "filter")
            delays.append((e["received"] - t) * 1000)
        delays.sort()
        figure("plc_set_to_opcua_event_ms_p50", round(statistics.median(delays), 1))
        figure("plc_set_to_opcua_event_ms_max", round(delays[-1], 1))
        await sub.delete()
        await sub_all.delete()
        await sub_values.delete()
        await sub_limits.delete()


async def run_flood(url, segment, plc_bin, count):
    count = int(count)
    async with Client(url, timeout=30) as client:
        events = Events()
        sub = await client.create_subscription(10, events)
        await sub.subscribe_events(ua.ObjectIds.Server, evfilter=event_filter(), queuesize=1000)

        async def all_of(active, what):
            t = time.perf_counter()
            deadline = time.monotonic() + 60
            while True:
                doors = {e["SourceName"] for e in events.got
                         if e["SourceName"].startswith("doors[") and e["ActiveState/Id"] == active}
                if len(doors) == count:
                    return time.perf_counter() - t
                check(time.monotonic() < deadline, f"{len(doors)} of {count} {what}")
                await asyncio.sleep(0.01)

        plc(plc_bin, "set", segment, "raise_all=true")
        took = await all_of(True, "raises")
        figure(f"opcua_{count}_alarm_raises_all_delivered_ms", round(took * 1000))
        ok(f"{count} alarms raised at once: every raise delivered ({took * 1000:.0f} ms)")

        events.got.clear()
        condition_type = client.get_node(ua.ObjectIds.ConditionType)
        await condition_type.call_method(REFRESH, ua.Variant(sub.subscription_id, ua.VariantType.UInt32))
        deadline = time.monotonic() + 30
        while len(events.got) < count + 2:
            check(time.monotonic() < deadline, f"ConditionRefresh: {len(events.got)} events")
            await asyncio.sleep(0.01)
        types = [e["EventType"] for e in events.got]
        check(types[0] == ua.NodeId(ua.ObjectIds.RefreshStartEventType)
              and types[-1] == ua.NodeId(ua.ObjectIds.RefreshEndEventType),
              "ConditionRefresh's events are not bracketed")
        check(len({e["SourceName"] for e in events.got[1:-1]}) == count, "ConditionRefresh")
        ok(f"ConditionRefresh: all {count} between RefreshStartEvent and RefreshEndEvent")

        events.got.clear()
        plc(plc_bin, "set", segment, "raise_all=false")
        took = await all_of(False, "returns")
        ok(f"{count} alarms back to normal: every return delivered ({took * 1000:.0f} ms)")
        await sub.delete()


async def run_conditions(url, segment, expected):
    want = sorted(expected.split(","))
    deadline = time.monotonic() + 15
    async with Client(url, timeout=30) as client:
        ns = await client.get_namespace_index(f"urn:plc-vars:{segment}")
        program = client.get_node(ua.NodeId(1, ns))
        while True:
            try:
                ids = [c.nodeid.Identifier for c in await program.get_children()]
                paths = sorted(i[:-len("#alarm")] for i in ids if str(i).endswith("#alarm"))
                linked = [await client.get_node(ua.NodeId(p, ns)).get_referenced_nodes(
                    ua.ObjectIds.HasCondition) for p in paths]
                linked = [[n.nodeid for n in nodes] for nodes in linked]
                names = [await client.get_node(ua.NodeId(f"{p}#alarm/ConditionName", ns)).read_value()
                         for p in paths]
            except ua.UaStatusCodeError:
                paths = None  # rebuilt between the browse and the reads: browse again
            if paths == want and names == want and all(
                    nodes == [ua.NodeId(f"{p}#alarm", ns)] for p, nodes in zip(paths, linked)):
                break
            check(time.monotonic() < deadline, f"expected the conditions {want}, still {paths}")
            await asyncio.sleep(0.1)
    ok(f"the program's conditions are {want}, each linked from its variable")


def main():
    try:
        if sys.argv[1] == "check":
            asyncio.run(run(*sys.argv[2:9]))
        elif sys.argv[1] == "conditions":
            asyncio.run(run_conditions(*sys.argv[2:5]))
        elif sys.argv[1] == "flood":
            asyncio.run(run_flood(*sys.argv[2:6]))
        else:
            raise Failed(f"unknown command {sys.argv[1]}")
    except Failed as e:
        print(f"FAILED: {e}", flush=True)
        sys.exit(1)


if __name__ == "__main__":
    main()
