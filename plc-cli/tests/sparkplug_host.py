"""An independent Sparkplug B host for plc-cli/tests/sparkplug.rs: paho-mqtt subscribes to a
group's messages, pysparkplug decodes them, and each arrives on stdout as one JSON line. The
test drives it with JSON lines on stdin: commands (NCMD rebirth, DCMD writes, raw bytes) and
the host's STATE, and floods of raw messages.

usage: sparkplug_host.py HOST PORT GROUP HOST_ID
"""

import json
import sys
import threading

import paho.mqtt.client as mqtt
import pysparkplug as spb
from pysparkplug._protobuf import Payload as PbPayload

host, port, group, host_id = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
births = {}  # device id (or None for the node) -> the last birth, to resolve aliases
out_lock = threading.Lock()


def say(obj):
    with out_lock:
        print(json.dumps(obj), flush=True)


def properties(raw):
    """Each metric's properties by name, from the raw protobuf (pysparkplug leaves them)."""
    pb = PbPayload.FromString(raw)
    found = {}
    for m in pb.metrics:
        props = {}
        for k, v in zip(m.properties.keys, m.properties.values):
            field = v.WhichOneof("value")
            props[k] = getattr(v, field) if field else None
        found[m.name] = props
    return found


def metric_json(m):
    value = m.value
    if isinstance(value, bytes):
        value = value.hex()
    return {
        "name": m.name,
        "alias": m.alias,
        "datatype": m.datatype.name,
        "value": value,
        "timestamp": m.timestamp,
        "is_historical": m.is_historical,
        "is_null": m.is_null,
    }


def on_message(client, userdata, msg):
    try:
        topic = spb.Topic.from_str(msg.topic)
        kind = topic.message_type.name if topic.message_type else "STATE"
        line = {"topic": msg.topic, "type": kind, "device": topic.device_id}
        if kind in ("NBIRTH", "DBIRTH"):
            cls = spb.NBirth if kind == "NBIRTH" else spb.DBirth
            p = cls.decode(msg.payload)
            births[topic.device_id] = p
            props = properties(msg.payload)
            line.update(seq=p.seq, timestamp=p.timestamp)
            line["metrics"] = [
                dict(metric_json(m), properties=props.get(m.name, {})) for m in p.metrics
            ]
        elif kind in ("NDATA", "DDATA"):
            cls = spb.NData if kind == "NDATA" else spb.DData
            p = cls.decode(msg.payload, birth=births.get(topic.device_id))
            line.update(seq=p.seq, timestamp=p.timestamp)
            line["metrics"] = [metric_json(m) for m in p.metrics]
        elif kind == "NDEATH":
            p = spb.NDeath.decode(msg.payload)
            line["bdSeq"] = p.bd_seq_metric.value
        elif kind == "DDEATH":
            p = spb.DDeath.decode(msg.payload)
            line.update(seq=p.seq, timestamp=p.timestamp)
        elif kind in ("NCMD", "DCMD"):
            line["size"] = len(msg.payload)
        else:
            line["payload"] = msg.payload.decode("utf-8", "replace")
        say(line)
    except Exception as e:  # a message this host cannot read is the test's finding
        say({"topic": msg.topic, "error": repr(e)})


def on_connect(client, userdata, flags, rc):
    client.subscribe(f"spBv1.0/{group}/#", qos=1)


def on_subscribe(client, userdata, mid, granted_qos):
    say({"ready": True})


client = mqtt.Client(client_id=f"sparkplug-test-host-{host_id}", clean_session=True)
client.on_connect = on_connect
client.on_message = on_message
client.on_subscribe = on_subscribe
client.connect(host, port, keepalive=30)
client.loop_start()

DATATYPES = {d.name: d for d in spb.DataType}

for raw_line in sys.stdin:
    cmd = json.loads(raw_line)
    op = cmd["op"]
    now = spb.get_current_timestamp()
    if op == "rebirth":
        node = cmd["node"]
        metric = spb.Metric(
            timestamp=now, name="Node Control/Rebirth", datatype=spb.DataType.BOOLEAN, value=True
        )
        payload = spb.NCmd(timestamp=now, metrics=(metric,)).encode(include_dtypes=True)
        client.publish(f"spBv1.0/{group}/NCMD/{node}", payload, qos=1).wait_for_publish()
    elif op == "dcmd":
        metric = spb.Metric(
            timestamp=now,
            name=cmd.get("name"),
            alias=cmd.get("alias"),
            datatype=DATATYPES[cmd["datatype"]],
            value=cmd["value"],
        )
        payload = spb.DCmd(timestamp=now, metrics=(metric,)).encode(include_dtypes=True)
        topic = f"spBv1.0/{group}/DCMD/{cmd['node']}/{cmd['device']}"
        client.publish(topic, payload, qos=1).wait_for_publish()
    elif op == "raw":
        data = bytes.fromhex(cmd.get("hex", "")) + b"\xff" * cmd.get("fill", 0)
        client.publish(cmd["topic"], data, qos=1).wait_for_publish()
    elif op == "flood":
        # As fast as the client sends: QoS 0, then one QoS 1 to know they all left.
        data = bytes.fromhex(cmd["hex"])
        for _ in range(cmd["count"] - 1):
            client.publish(cmd["topic"], data, qos=0)
        client.publish(cmd["topic"], data, qos=1).wait_for_publish()
    elif op == "state":
        payload = json.dumps({"online": cmd["online"], "timestamp": cmd.get("timestamp", now)})
        client.publish(f"spBv1.0/STATE/{host_id}", payload, qos=1, retain=True).wait_for_publish()
    say({"done": op})

client.loop_stop()
