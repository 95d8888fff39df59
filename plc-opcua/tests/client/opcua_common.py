"""What the OPC UA test clients share (`opcua_client.py`, `opcua_attack.py`,
`opcua_alarms.py`): failing and passing checks, running `plc`, values as `plc get` prints them,
statuses of reads and writes, a user's session over Sign, and figure lines."""

import hashlib
import itertools
import shutil
import socket
import subprocess
from pathlib import Path

from asyncua import Client, ua
from asyncua.crypto import security_policies
from asyncua.crypto.cert_gen import setup_self_signed_certificate
from cryptography.x509.oid import ExtendedKeyUsageOID


# IEC 61131-3 elementary types and their OPC UA built-in DataTypes (ns=0 numeric ids).
DATA_TYPES = {
    "BOOL": ua.ObjectIds.Boolean, "SINT": ua.ObjectIds.SByte, "USINT": ua.ObjectIds.Byte,
    "BYTE": ua.ObjectIds.Byte, "INT": ua.ObjectIds.Int16, "UINT": ua.ObjectIds.UInt16,
    "WORD": ua.ObjectIds.UInt16, "DINT": ua.ObjectIds.Int32, "UDINT": ua.ObjectIds.UInt32,
    "DWORD": ua.ObjectIds.UInt32, "LINT": ua.ObjectIds.Int64, "ULINT": ua.ObjectIds.UInt64,
    "LWORD": ua.ObjectIds.UInt64, "REAL": ua.ObjectIds.Float, "LREAL": ua.ObjectIds.Double,
    "STRING": ua.ObjectIds.String, "LTIME": ua.ObjectIds.Duration,
}
READ = ua.AccessLevel.CurrentRead.mask
WRITE = ua.AccessLevel.CurrentWrite.mask


class Failed(Exception):
    pass


def check(condition, what):
    if not condition:
        raise Failed(what)


def ok(what):
    print(f"ok: {what}", flush=True)


def plc(plc_bin, *args):
    out = subprocess.run([plc_bin, *args], capture_output=True, text=True, timeout=30)
    check(out.returncode == 0, f"`plc {' '.join(args)}` failed: {out.stderr}")
    return out.stdout


def plc_get(plc_bin, segment, names):
    values = {}
    for line in plc(plc_bin, "get", segment, *names).splitlines():
        name, _, value = line.partition(" = ")
        values[name] = value
    return values


def as_plc_text(iec_type, value):
    """A value read over OPC UA as `plc get` prints it."""
    if iec_type == "BOOL":
        return "true" if value else "false"
    if iec_type in ("REAL", "LREAL"):
        return None  # compared as numbers
    return str(value)


LTIME_UNITS = {"d": 86_400_000, "h": 3_600_000, "m": 60_000, "s": 1000, "ms": 1,
               "us": 1e-3, "ns": 1e-6}


def ltime_ms(text):
    """A duration as `plc get` prints it for a person (`90.5 s`, exact unless digits are asked
    for) or as an IEC literal (`LTIME#1m30s500ms`), in milliseconds."""
    import re
    from decimal import Decimal, InvalidOperation
    if text.endswith(" s"):
        try:
            return float(Decimal(text[:-2]) * 1000)
        except InvalidOperation:
            check(False, f"not a duration: {text!r}")
    check("#" in text, f"not a duration: {text!r}")
    body = text.split("#", 1)[1].replace("_", "")
    sign = -1 if body.startswith("-") else 1
    parts = re.findall(r"(\d+(?:\.\d+)?)(ms|us|ns|d|h|m|s)", body.lstrip("+-"))
    check(parts, f"not a duration: {text!r}")
    return sign * sum(float(n) * LTIME_UNITS[u] for n, u in parts)


def same_value(iec_type, plc_text, value):
    if iec_type in ("REAL", "LREAL"):
        return float(plc_text) == float(value)
    if iec_type == "LTIME":
        # OPC UA's Duration is a Double of milliseconds.
        return abs(ltime_ms(plc_text) - float(value)) < 1e-6
    return as_plc_text(iec_type, value) == plc_text


def flatten(variables, prefix="", parent_writable=None):
    """The basic values of `plc list --json`'s variables, each with its path (its NodeId), its
    BrowseName and whether a tool may write it: a structure's members by path, an array of
    structures element by element (`axes[1].pos`)."""
    out = []
    for v in variables:
        path = prefix + v["name"]
        if parent_writable is None:
            writable = v["access"] == "read_write" and v["direction"] not in ("input", "status")
        else:
            writable = parent_writable and v["access"] == "read_write"
        if v.get("members"):
            dims = v.get("dims") or []
            elements = itertools.product(*[range(d) for d in dims]) if dims else [None]
            for coords in elements:
                at = path if coords is None else f"{path}[{','.join(map(str, coords))}]"
                out += flatten(v["members"], at + ".", writable)
        else:
            out.append(dict(v, path=path, browse=v["name"], writable=writable,
                            top=parent_writable is None))
    return out


async def browse_variables(node, found, depth=0):
    """Every variable under `node`, through objects (a structure level is an object), the
    alarms' conditions left out."""
    check(depth < 16, "the tree is deeper than 16 levels")
    for child in await node.get_children():
        cls = await child.read_node_class()
        if cls == ua.NodeClass.Variable:
            found.append(child)
        elif cls == ua.NodeClass.Object:
            if "#alarm" in str(child.nodeid.Identifier):
                continue  # an alarm's condition: opcua_alarms.py checks those
            await browse_variables(child, found, depth + 1)


async def status_of(client, node_id, attribute=ua.AttributeIds.Value):
    """The DataValue of an attribute, a bad status included (asyncua's own read raises)."""
    res = await client.uaclient.read(ua.ReadParameters(NodesToRead=[
        ua.ReadValueId(NodeId=node_id, AttributeId=attribute)]))
    return res[0]


async def write_status(client, node_id, variant):
    params = ua.WriteParameters(NodesToWrite=[ua.WriteValue(
        NodeId=node_id, AttributeId=ua.AttributeIds.Value, Value=ua.DataValue(variant))])
    return (await client.uaclient.write(params))[0]


async def write_range(client, node_id, values, index_range):
    variant = ua.Variant(values, ua.VariantType.Int16)
    params = ua.WriteParameters(NodesToWrite=[ua.WriteValue(
        NodeId=node_id, AttributeId=ua.AttributeIds.Value, IndexRange=index_range,
        Value=ua.DataValue(variant))])
    return (await client.uaclient.write(params))[0]


def expect_status(status, name, what):
    check(status.name == name, f"{what}: expected {name}, got {status.name}")
    ok(f"{what}: {name}")



async def user_client(url, user, password, pki, workdir):
    """A user's client as a careful HMI connects: Basic256Sha256 Sign, its certificate trusted
    by the server (placed in the server's pki/trusted/ under the name the server looks for)."""
    key, cert = Path(workdir) / "hmi-key.pem", Path(workdir) / "hmi-cert.der"
    app_uri = "urn:plc-vars:test-hmi"
    async def make():
        # Patient: a name that failed waits up to 5 s before its password is checked.
        client = Client(url, timeout=30)
        client.application_uri = app_uri
        client.set_user(user)
        client.set_password(password)
        await client.set_security(security_policies.SecurityPolicyBasic256Sha256, str(cert),
                                  str(key), mode=ua.MessageSecurityMode.Sign)
        return client

    if not cert.exists():
        await setup_self_signed_certificate(key, cert, app_uri, socket.gethostname(),
                                            [ExtendedKeyUsageOID.CLIENT_AUTH], {"commonName": "plc-vars hmi"})
        # As an operator trusts a new HMI: its first try is refused and its certificate kept
        # in pki/rejected/, from where it is moved to pki/trusted/.
        try:
            first = await make()
            await first.connect()
            await first.disconnect()
            raise Failed("an untrusted HMI certificate was accepted")
        except Failed:
            raise
        except Exception:
            pass
        thumbprint = hashlib.sha1(cert.read_bytes()).hexdigest()
        found = [f for f in (Path(pki) / "rejected").glob("*.der") if f"[{thumbprint}]" in f.name]
        check(len(found) == 1, f"the HMI's certificate is not in {pki}/rejected")
        shutil.move(str(found[0]), str(Path(pki) / "trusted" / found[0].name))
    return await make()


def figure(name, value):
    print(f"figure: {name}: {value}", flush=True)
