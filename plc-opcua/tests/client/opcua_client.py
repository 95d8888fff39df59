"""An independent OPC UA client (python asyncua) against `plc opcua serve` and a running program.

    opcua_client.py check URL SEGMENT PLC PKI WORKDIR USER PASSWORD
        browse the whole tree, check every node's attributes against `plc list --json`, read
        every variable and compare with `plc get`, subscribe, write as a user and see it in
        `plc get`, the refused writes and their status codes, a plain-text password refused,
        a SignAndEncrypt session (its client certificate trusted through the server's pki)
    opcua_client.py names URL SEGMENT NAME,NAME...
        the program's variables, once the namespace shows exactly these (after a new
        declaration), each read Good, an array with its dimensions
    opcua_client.py values URL SEGMENT good|bad
        every variable's status: Good, or BadNoCommunication (the program is gone)
    opcua_client.py ranges URL SEGMENT USER PASSWORD PKI WORKDIR
        writes with index ranges to `row` (INT[6]) and `plane` (INT[2,3]) set exactly the
        selected elements; a range past the end or of the wrong rank is refused; a change made
        while a monitored item is Disabled is reported once it is enabled again
    opcua_client.py forced URL SEGMENT USER PASSWORD PKI WORKDIR
        with `setpoint` (LREAL) forced to 2.5 and `row[2]` (INT[4]) to 40: both read with their
        forced value and GoodLocalOverride, `feed` beside them Good, their AccessLevel as
        before; a write of `setpoint` or of the whole `row` is refused with BadLocked and
        changes nothing, a write of `row[0]` alone is applied
    opcua_client.py released URL SEGMENT USER PASSWORD PKI WORKDIR
        once released: `setpoint` and `row` read Good, and a write of `setpoint` = 7 is applied

    opcua_client.py attack URL SEGMENT USER PASSWORD PKI WORKDIR SERVER_PID
        as attackers on loopback would: 30 anonymous sessions from one address, then an
        operator from another signs in and writes; 100,000 monitored items in one call while
        another client reads; 200 failed sign-ins 40 at a time, the server's memory bounded and
        the operator's sign-in working after. Prints `figure:` lines.

Users connect as an HMI does, over Basic256Sha256 Sign with a certificate the server trusts
(PKI is the server's certificate store, WORKDIR where the client's certificate is made).

Prints one `ok:` line per check; exits 1 with `FAILED:` and the reason on the first that fails.
"""

import asyncio
import json
import math
import shutil
import socket
import sys
import time
from pathlib import Path

from asyncua import Client, ua
from asyncua.crypto import security_policies
from asyncua.crypto.cert_gen import setup_self_signed_certificate
from cryptography.x509.oid import ExtendedKeyUsageOID


from opcua_common import (
    DATA_TYPES,
    Failed,
    READ,
    WRITE,
    browse_variables,
    check,
    expect_status,
    flatten,
    ok,
    plc,
    plc_get,
    same_value,
    status_of,
    user_client,
    write_range,
    write_status,
)
from opcua_attack import run_attack, run_read100


async def address_space(client, segment, variables):
    ns = await client.get_namespace_index(f"urn:plc-vars:{segment}")
    program = None
    for child in await client.nodes.objects.get_children():
        if (await child.read_browse_name()) == ua.QualifiedName(segment, ns):
            program = child
    check(program is not None, f"no object `{segment}` under Objects")
    ok(f"namespace urn:plc-vars:{segment} is ns={ns}, object `{segment}` under Objects")
    nodes = []
    await browse_variables(program, nodes)
    by_name = {}
    for node in nodes:
        by_name[node.nodeid.Identifier] = node
    paths = sorted(v["path"] for v in variables)
    check(sorted(by_name) == paths, f"browsed {sorted(by_name)}, the program has {paths}")
    structured = sum(1 for v in variables if not v["top"])
    ok(f"browsed the whole tree: {len(nodes)} variables, the program's own ({structured} of "
       f"them members of structures, under an object per structure)")
    for var in variables:
        name = var["path"]
        node = by_name[name]
        check(node.nodeid == ua.NodeId(name, ns), f"{name}: NodeId {node.nodeid}")
        browse = var["browse"]
        check((await node.read_browse_name()) == ua.QualifiedName(browse, ns),
              f"{name}: BrowseName")
        check((await node.read_display_name()).Text == browse, f"{name}: DisplayName")
        desc = (await node.read_description()).Text or ""
        check(desc == var.get("description", ""), f"{name}: Description {desc!r}")
        dtype = await node.read_data_type()
        check(dtype == ua.NodeId(DATA_TYPES[var["iec_type"]]), f"{name}: DataType {dtype}")
        rank = await node.read_value_rank()
        check(rank == (len(var["dims"]) if var.get("dims") else -1), f"{name}: ValueRank {rank}")
        writable = var["writable"]
        level = (await node.read_attribute(ua.AttributeIds.AccessLevel)).Value.Value
        check(level == (READ | WRITE if writable else READ), f"{name}: AccessLevel {level}")
        user_level = (await node.read_attribute(ua.AttributeIds.UserAccessLevel)).Value.Value
        check(user_level == READ, f"{name}: anonymous UserAccessLevel {user_level}")
    ok("every node: NodeId ns;s=<path>, BrowseName, DisplayName, Description, DataType, "
       "ValueRank, AccessLevel; UserAccessLevel read-only for anonymous")
    return ns, by_name


async def values_match_plc_get(client, plc_bin, segment, variables, by_name):
    names = [v["path"] for v in variables]
    # Values the program changes every cycle differ between the two `plc get`s: the others
    # must be most of them, and every command and internal variable.
    steady = [v for v in variables if v["top"] and v["direction"] in ("command", "internal")]
    # An input that flickers (a drive's statusword bit) can read the same in both `plc get`s
    # and another value in between: such a difference must not hold in every attempt.
    persistent = None
    for attempt in range(5):
        before = plc_get(plc_bin, segment, names)
        values = await client.read_values([by_name[n] for n in names])
        data = await client.uaclient.read(ua.ReadParameters(NodesToRead=[
            ua.ReadValueId(NodeId=by_name[n].nodeid, AttributeId=ua.AttributeIds.Value)
            for n in names]))
        after = plc_get(plc_bin, segment, names)
        stable = [v for v in variables if before[v["path"]] == after[v["path"]]]
        mismatched = set()
        for var, value in zip(variables, values):
            if var in stable and not same_value(var["iec_type"], before[var["path"]], value):
                check(var not in steady,
                      f"{var['path']}: OPC UA read {value!r}, `plc get` {before[var['path']]!r}")
                mismatched.add(var["path"])
        persistent = mismatched if persistent is None else persistent & mismatched
        now = time.time()
        for n, dv in zip(names, data):
            check(dv.StatusCode.is_good(), f"{n}: status {dv.StatusCode}")
            age = now - dv.SourceTimestamp.timestamp()
            check(-1 < age < 5, f"{n}: SourceTimestamp {dv.SourceTimestamp} is {age:.1f} s old")
        if all(v in stable for v in steady) and not mismatched:
            ok(f"read every variable: {len(stable)} of {len(variables)} unchanged during the "
               f"read, each equal to `plc get`; all Good, SourceTimestamp the cycle's time")
            return
    check(not persistent, f"{sorted(persistent)}: the OPC UA read differs from `plc get` in "
                          "every attempt")
    raise Failed("command and internal variables kept changing during five reads")


class Counter:
    def __init__(self):
        self.values = []

    def datachange_notification(self, node, val, data):
        self.values.append(val)


async def subscription(client, node):
    counter = Counter()
    sub = await client.create_subscription(
        ua.CreateSubscriptionParameters(RequestedPublishingInterval=10, RequestedLifetimeCount=1000,
                                        RequestedMaxKeepAliveCount=100, MaxNotificationsPerPublish=0,
                                        PublishingEnabled=True, Priority=0), counter)
    check(sub.parameters.RequestedPublishingInterval <= 10,
          f"publishing interval revised to {sub.parameters.RequestedPublishingInterval} ms")
    await sub.subscribe_data_change(node, sampling_interval=1)
    await asyncio.sleep(2.0)
    distinct = len(set(counter.values))
    check(distinct >= 20, f"{distinct} changes of {node.nodeid.Identifier} in 2 s")
    ok(f"subscription to {node.nodeid.Identifier}: {distinct} changes in 2 s (publishing 10 ms)")
    # Disabled: nothing more (after what was on its way), though the value goes on changing.
    await sub.set_monitoring_mode(ua.MonitoringMode.Disabled)
    await asyncio.sleep(0.2)
    counter.values.clear()
    await asyncio.sleep(0.5)
    check(not counter.values, f"{len(counter.values)} notifications while Disabled")
    await sub.set_monitoring_mode(ua.MonitoringMode.Reporting)
    await asyncio.sleep(0.5)
    check(len(counter.values) >= 5, f"{len(counter.values)} notifications once Reporting again")
    ok("no notifications while the item is Disabled, again once it is Reporting")
    await sub.delete()


def plain_text_policy(token_type):
    """What a careless client does: the user name token's password sent as it is."""
    return ua.UserTokenPolicy(PolicyId="userpass_rsa_oaep", TokenType=token_type,
                              SecurityPolicyUri=None)


async def refused_plain_text(url, user, password):
    client = Client(url)
    client.set_user(user)
    client.set_password(password)
    client.server_policy = plain_text_policy
    try:
        await client.connect()
    except Exception as e:  # the session is refused; what asyncua raises says why
        text = f"{type(e).__name__}: {e}"
        check("BadIdentityTokenRejected" in text,
              f"a plain-text password was refused, but not for its token: {text}")
        ok(f"a user name token with a plain-text password is refused ({text[:80]})")
        return
    await client.disconnect()
    raise Failed("a user name token with a plain-text password was accepted")


async def writes(url, plc_bin, segment, ns, user, password, pki, workdir):
    client = await user_client(url, user, password, pki, workdir)
    async with client:
        node = lambda name: client.get_node(ua.NodeId(name, ns))
        speed = node("test_speed_mm_s")
        level = (await speed.read_attribute(ua.AttributeIds.UserAccessLevel)).Value.Value
        check(level == READ | WRITE, f"a user's UserAccessLevel of test_speed_mm_s is {level}")
        ok("a signed-in user's UserAccessLevel includes CurrentWrite")
        old = plc_get(plc_bin, segment, ["test_speed_mm_s"])["test_speed_mm_s"]
        new = 3.25 if float(old) != 3.25 else 4.5
        status = await write_status(client, speed.nodeid, ua.Variant(new, ua.VariantType.Double))
        expect_status(status, "Good", f"write test_speed_mm_s = {new} as `{user}`")
        deadline = time.time() + 5
        while float(plc_get(plc_bin, segment, ["test_speed_mm_s"])["test_speed_mm_s"]) != new:
            check(time.time() < deadline, "the written value never showed in `plc get`")
            await asyncio.sleep(0.05)
        ok(f"`plc get` shows test_speed_mm_s = {new}")
        refusals = [
            ("ls_lift_neg", ua.Variant(True, ua.VariantType.Boolean), "BadNotWritable", "an input"),
            ("force_kn", ua.Variant(1.0, ua.VariantType.Double), "BadNotWritable", "a status"),
            ("impact67_0_digital_outputs", ua.Variant(70000, ua.VariantType.Int32),
             "BadOutOfRange", "70000 to a UINT"),
            ("test_speed_mm_s", ua.Variant(math.nan, ua.VariantType.Double), "BadOutOfRange", "NaN"),
            ("info_test_id", ua.Variant("x" * 65, ua.VariantType.String), "BadOutOfRange",
             "65 bytes to a STRING(64)"),
            ("test_speed_mm_s", ua.Variant("fast", ua.VariantType.String), "BadTypeMismatch",
             "text to an LREAL"),
            ("axes[0].moves", ua.Variant(5, ua.VariantType.UInt32), "BadNotWritable",
             "a read-only member of a structure"),
        ]
        for name, variant, expected, what in refusals:
            status = await write_status(client, node(name).nodeid, variant)
            expect_status(status, expected, f"write {what} ({name})")
        check(float(plc_get(plc_bin, segment, ["test_speed_mm_s"])["test_speed_mm_s"]) == new,
              "a refused write changed test_speed_mm_s")
        # A member inside an array of structures goes through the same write path (the
        # program sets the IN parameter again in its next cycle).
        status = await write_status(client, node("axes[2].enable").nodeid,
                                    ua.Variant(True, ua.VariantType.Boolean))
        expect_status(status, "Good", "write an IN parameter of a structure (axes[2].enable)")
        await write_status(client, speed.nodeid, ua.Variant(float(old), ua.VariantType.Double))


async def sign_and_encrypt(url, pki, workdir, user, password, ns):
    key, cert = Path(workdir) / "client-key.pem", Path(workdir) / "client-cert.der"
    app_uri = "urn:plc-vars:test-client"
    await setup_self_signed_certificate(key, cert, app_uri, socket.gethostname(),
                                        [ExtendedKeyUsageOID.CLIENT_AUTH], {"commonName": "plc-vars test"})

    async def connect():
        client = Client(url)
        client.application_uri = app_uri
        client.set_user(user)
        client.set_password(password)
        await client.set_security(security_policies.SecurityPolicyBasic256Sha256, str(cert), str(key),
                                  mode=ua.MessageSecurityMode.SignAndEncrypt)
        await client.connect()
        return client

    try:
        client = await connect()
        await client.disconnect()
        raise Failed("an untrusted client certificate was accepted")
    except Failed:
        raise
    except Exception:
        pass
    rejected = list((Path(pki) / "rejected").glob("*.der"))
    check(len(rejected) == 1, f"the refused certificate is not in {pki}/rejected: {rejected}")
    shutil.move(str(rejected[0]), str(Path(pki) / "trusted" / rejected[0].name))
    ok("an untrusted client certificate is refused and kept in pki/rejected; moved to trusted/")
    client = await connect()
    try:
        check(client.security_policy.Mode == ua.MessageSecurityMode.SignAndEncrypt, "mode")
        value = await client.get_node(ua.NodeId("tests_completed", ns)).read_value()
        ok(f"a Basic256Sha256 SignAndEncrypt session as `{user}` reads tests_completed = {value}")
    finally:
        await client.disconnect()


async def endpoints(url):
    found = {(e.SecurityPolicyUri.split("#")[-1], e.SecurityMode.name)
             for e in await Client(url).connect_and_get_server_endpoints()}
    for wanted in [("None", "None_"), ("Basic256Sha256", "Sign"), ("Basic256Sha256", "SignAndEncrypt")]:
        check(wanted in found, f"no endpoint {wanted}: {found}")
    ok(f"endpoints: {sorted(found)}")


async def run_check(url, segment, plc_bin, pki, workdir, user, password):
    variables = flatten(json.loads(plc(plc_bin, "list", segment, "--json"))["variables"])
    await endpoints(url)
    async with Client(url) as client:
        ns, by_name = await address_space(client, segment, variables)
        await values_match_plc_get(client, plc_bin, segment, variables, by_name)
        await subscription(client, by_name["state_cycles"])
        status = await write_status(client, by_name["cmd_start"].nodeid,
                                    ua.Variant(True, ua.VariantType.Boolean))
        expect_status(status, "BadUserAccessDenied", "anonymous write of cmd_start")
    await refused_plain_text(url, user, password)
    await unsigned_user_refused(url, user, password)
    await writes(url, plc_bin, segment, ns, user, password, pki, workdir)
    await sign_and_encrypt(url, pki, workdir, user, password, ns)


async def run_values(url, segment, expected):
    """Waits (at most 15 s) until every value has the expected status."""
    want = "Good" if expected == "good" else "BadNoCommunication"
    deadline = time.time() + 15
    async with Client(url) as client:
        ns = await client.get_namespace_index(f"urn:plc-vars:{segment}")
        nodes = []
        await browse_variables(client.get_node(ua.NodeId(1, ns)), nodes)
        check(nodes, "no variables to read")
        while True:
            data = await client.uaclient.read(ua.ReadParameters(NodesToRead=[
                ua.ReadValueId(NodeId=n.nodeid, AttributeId=ua.AttributeIds.Value) for n in nodes]))
            names = {dv.StatusCode.name for dv in data}
            if names == {want}:
                ok(f"all {len(nodes)} values {want}")
                return
            check(time.time() < deadline, f"expected every value {want}, still {names} after 15 s")
            await asyncio.sleep(0.1)


async def run_names(url, segment, expected):
    """Waits (at most 15 s) until the program object holds exactly the variables `expected`."""
    want = sorted(expected.split(","))
    deadline = time.time() + 15
    async with Client(url) as client:
        ns = await client.get_namespace_index(f"urn:plc-vars:{segment}")
        while True:
            nodes = []
            try:
                await browse_variables(client.get_node(ua.NodeId(1, ns)), nodes)
                names = sorted([(await n.read_browse_name()).Name for n in nodes])
            except ua.uaerrors.BadNodeIdUnknown:
                # The server rebuilt the namespace between the browse and the read: the nodes
                # browsed are gone. Browse again.
                names = None
            if names == want:
                break
            check(time.time() < deadline, f"expected the variables {want}, still {names} after 15 s")
            await asyncio.sleep(0.1)
        while True:
            data = [await status_of(client, n.nodeid) for n in nodes]
            if all(dv.StatusCode.is_good() for dv in data):
                break
            check(time.time() < deadline, f"values not Good: {[dv.StatusCode.name for dv in data]}")
            await asyncio.sleep(0.1)
        for node, dv in zip(nodes, data):
            dims = await status_of(client, node.nodeid, ua.AttributeIds.ArrayDimensions)
            if dims.StatusCode.is_good() and dims.Value.Value:
                dims = dims.Value.Value
                check(len(dv.Value.Value) == math.prod(dims), f"{node.nodeid}: {dv.Value}")
        ok(f"the namespace holds {names}, every value Good")


async def run_ranges(url, segment, user, password, pki, workdir):
    async with await user_client(url, user, password, pki, workdir) as client:
        ns = await client.get_namespace_index(f"urn:plc-vars:{segment}")
        row = client.get_node(ua.NodeId("row", ns))
        plane = client.get_node(ua.NodeId("plane", ns))

        async def becomes(node, want, what):
            deadline = time.time() + 5
            while (got := list(await node.read_value())) != want:
                check(time.time() < deadline, f"{what}: expected {want}, still {got}")
                await asyncio.sleep(0.02)
            ok(f"{what}: {want}")

        expect_status(await write_range(client, row.nodeid, [7, 8, 9], "2:4"), "Good",
                      "write row[2:4]")
        await becomes(row, [0, 0, 7, 8, 9, 0], "row after writing elements 2 to 4")
        expect_status(await write_range(client, row.nodeid, [5], "5"), "Good", "write row[5]")
        await becomes(row, [0, 0, 7, 8, 9, 5], "row after writing element 5")
        # Row 1, columns 0 and 1: row-major elements 3 and 4.
        expect_status(await write_range(client, plane.nodeid, [1, 2], "1,0:1"), "Good",
                      "write plane[1,0:1]")
        await becomes(plane, [[0, 0, 0], [1, 2, 0]], "plane after writing [1,0:1]")
        for node, values, index_range, expected, what in [
            (row, [1, 2], "5:6", "BadIndexRangeNoData", "a range past the end"),
            (row, [1, 2], "1:3", "BadTypeMismatch", "two values for three elements"),
            (plane, [1], "1", "BadIndexRangeInvalid", "one index for two dimensions"),
        ]:
            expect_status(await write_range(client, node.nodeid, values, index_range), expected,
                          f"write {what} ({index_range})")
        await becomes(row, [0, 0, 7, 8, 9, 5], "row unchanged by the refused writes")

        # A value that changed while its item was Disabled is reported once it is enabled again,
        # also while another item keeps sampling the same node.
        other = await client.create_subscription(10, Counter())
        await other.subscribe_data_change(row, sampling_interval=1)
        counter = Counter()
        sub = await client.create_subscription(10, counter)
        await sub.subscribe_data_change(row, sampling_interval=1)
        await asyncio.sleep(0.3)
        check(counter.values and list(counter.values[-1]) == [0, 0, 7, 8, 9, 5],
              f"the first notification of row: {counter.values}")
        await sub.set_monitoring_mode(ua.MonitoringMode.Disabled)
        await asyncio.sleep(0.1)
        counter.values.clear()
        expect_status(await write_range(client, row.nodeid, [1], "0"), "Good", "write row[0]")
        await asyncio.sleep(0.3)
        check(not counter.values, f"notified while Disabled: {counter.values}")
        await sub.set_monitoring_mode(ua.MonitoringMode.Reporting)
        deadline = time.time() + 2
        while not counter.values:
            check(time.time() < deadline, "no notification of row once Reporting again")
            await asyncio.sleep(0.02)
        check(list(counter.values[-1]) == [1, 0, 7, 8, 9, 5], f"row once enabled: {counter.values}")
        ok("a change made while the item was Disabled is reported once it is enabled")
        await sub.delete()
        await other.delete()

        # Arrays larger than 64 elements (a request held 64 writes once): written whole, in
        # one cycle; one larger than a cycle's request is refused at once and written in parts.
        table = client.get_node(ua.NodeId("table", ns))
        values = [k * 3 - 1000 for k in range(1000)]
        status = await write_status(client, table.nodeid, ua.Variant(values, ua.VariantType.Int32))
        expect_status(status, "Good", "write the whole table (1,000 DINTs)")
        await becomes(table, values, "table after its whole write")
        ok("an array of 1,000 elements written whole is applied")
        huge = client.get_node(ua.NodeId("huge", ns))
        t = time.perf_counter()
        status = await write_status(client, huge.nodeid, ua.Variant([5] * 1100, ua.VariantType.Int16))
        expect_status(status, "BadTooManyOperations", "write 1,100 elements whole")
        check(time.perf_counter() - t < 2, "the refusal took as long as a timeout")
        expect_status(await write_range(client, huge.nodeid, [5] * 1000, "0:999"), "Good",
                      "write huge[0:999]")
        expect_status(await write_range(client, huge.nodeid, [6] * 100, "1000:1099"), "Good",
                      "write huge[1000:1099]")
        await becomes(huge, [5] * 1000 + [6] * 100, "huge after two parts")
        ok("1,100 elements whole: BadTooManyOperations at once; in two parts: applied")


async def unsigned_user_refused(url, user, password):
    """A user over None: the None endpoint offers no user name, and a client that sends one
    anyway is refused; the session never gets to write."""
    for e in await Client(url).connect_and_get_server_endpoints():
        if e.SecurityMode == ua.MessageSecurityMode.None_:
            kinds = [t.TokenType for t in e.UserIdentityTokens]
            check(ua.UserTokenType.UserName not in kinds,
                  f"the None endpoint offers user names: {kinds}")
    ok("the None endpoint offers anonymous sign-in only")
    client = Client(url)
    client.set_user(user)
    client.set_password(password)
    # What a careless client does: the user name policy of a signed endpoint, over None.
    client.server_policy = lambda token_type: ua.UserTokenPolicy(
        PolicyId="userpass_rsa_oaep", TokenType=token_type,
        SecurityPolicyUri=security_policies.SecurityPolicyBasic256Sha256.URI)
    try:
        await client.connect()
    except Exception as e:
        text = f"{type(e).__name__}: {e}"
        check("BadIdentityTokenRejected" in text or "BadSecurityModeInsufficient" in text
              or "BadUserAccessDenied" in text, f"refused, but why? {text}")
        ok(f"a user's sign-in over None is refused ({text[:90]})")
        return
    try:
        status = await write_status(client, ua.NodeId("test_speed_mm_s", 2),
                                    ua.Variant(1.0, ua.VariantType.Double))
        raise Failed(f"a user signed in over None (a write answered {status.name})")
    finally:
        await client.disconnect()


async def becomes_status(client, node_id, want, what):
    """Waits (at most 5 s) until the node's value reads with status `want`; its DataValue."""
    deadline = time.time() + 5
    while (dv := await status_of(client, node_id)).StatusCode.name != want:
        check(time.time() < deadline, f"{what}: expected {want}, still {dv.StatusCode.name}")
        await asyncio.sleep(0.02)
    return dv


async def run_forced(url, segment, user, password, pki, workdir):
    async with await user_client(url, user, password, pki, workdir) as client:
        ns = await client.get_namespace_index(f"urn:plc-vars:{segment}")
        setpoint, feed, row = (ua.NodeId(n, ns) for n in ("setpoint", "feed", "row"))
        dv = await becomes_status(client, setpoint, "GoodLocalOverride", "forced setpoint")
        check(dv.Value.Value == 2.5, f"forced setpoint reads {dv.Value.Value}")
        ok("the forced setpoint reads 2.5, GoodLocalOverride")
        dv = await becomes_status(client, row, "GoodLocalOverride", "row with row[2] forced")
        check(list(dv.Value.Value)[2] == 40, f"row reads {dv.Value.Value}")
        ok(f"row, its element 2 forced, reads {list(dv.Value.Value)}, GoodLocalOverride")
        expect_status((await status_of(client, feed)).StatusCode, "Good", "feed, not forced")
        for node_id in (setpoint, row):
            level = (await status_of(client, node_id, ua.AttributeIds.AccessLevel)).Value.Value
            check(level == READ | WRITE, f"{node_id.Identifier}: AccessLevel {level}")
        ok("a forced node's AccessLevel is unchanged (writable once released)")
        status = await write_status(client, setpoint, ua.Variant(7.0, ua.VariantType.Double))
        expect_status(status, "BadLocked", "write the forced setpoint")
        status = await write_status(client, row, ua.Variant([1, 2, 3, 4], ua.VariantType.Int16))
        expect_status(status, "BadLocked", "write the whole row, its element 2 forced")
        expect_status(await write_range(client, row, [9], "0"), "Good",
                      "write row[0], not forced")
        deadline = time.time() + 5
        while (got := list(await client.get_node(row).read_value())) != [9, 0, 40, 0]:
            check(time.time() < deadline, f"row: expected [9, 0, 40, 0], still {got}")
            await asyncio.sleep(0.02)
        check(await client.get_node(setpoint).read_value() == 2.5,
              "a refused write changed the forced setpoint")
        ok(f"row is {got}: the refused writes changed nothing")


async def run_released(url, segment, user, password, pki, workdir):
    async with await user_client(url, user, password, pki, workdir) as client:
        ns = await client.get_namespace_index(f"urn:plc-vars:{segment}")
        setpoint, row = ua.NodeId("setpoint", ns), ua.NodeId("row", ns)
        await becomes_status(client, setpoint, "Good", "released setpoint")
        await becomes_status(client, row, "Good", "released row")
        ok("released, setpoint and row read Good")
        status = await write_status(client, setpoint, ua.Variant(7.0, ua.VariantType.Double))
        expect_status(status, "Good", "write the released setpoint = 7")
        deadline = time.time() + 5
        while (got := await client.get_node(setpoint).read_value()) != 7.0:
            check(time.time() < deadline, f"setpoint: expected 7.0, still {got}")
            await asyncio.sleep(0.02)
        ok("setpoint reads 7.0")


def main():
    try:
        if sys.argv[1] == "check":
            asyncio.run(run_check(*sys.argv[2:9]))
        elif sys.argv[1] == "names":
            asyncio.run(run_names(*sys.argv[2:5]))
        elif sys.argv[1] == "values":
            asyncio.run(run_values(*sys.argv[2:5]))
        elif sys.argv[1] == "ranges":
            asyncio.run(run_ranges(*sys.argv[2:8]))
        elif sys.argv[1] == "forced":
            asyncio.run(run_forced(*sys.argv[2:8]))
        elif sys.argv[1] == "attack":
            asyncio.run(run_attack(*sys.argv[2:9]))
        elif sys.argv[1] == "read100":
            asyncio.run(run_read100(*sys.argv[2:5]))
        elif sys.argv[1] == "released":
            asyncio.run(run_released(*sys.argv[2:8]))
        else:
            raise Failed(f"unknown command {sys.argv[1]}")
    except Failed as e:
        print(f"FAILED: {e}", flush=True)
        sys.exit(1)


if __name__ == "__main__":
    main()
