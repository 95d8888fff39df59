#!/usr/bin/env bash
# Runs every test of the workspace. Some tests drive real system tools: `plc watch` runs in
# tmux, the simulated EtherCAT bus is also tested over a veth pair (iproute2), and the Sparkplug
# edge node publishes to a real MQTT broker (mosquitto). Install them when missing and we may
# (root, or passwordless sudo); tests that still lack them say so and skip.
set -euo pipefail
cd "$(dirname "$0")/.."

as_root=()
[[ $(id -u) == 0 ]] || as_root=(sudo -n)
need=()
command -v tmux >/dev/null 2>&1 || need+=(tmux)
command -v ip >/dev/null 2>&1 || need+=(iproute2)
# Debian installs the broker in /usr/sbin, which a user's PATH may not hold.
command -v mosquitto >/dev/null 2>&1 || [[ -x /usr/sbin/mosquitto ]] || need+=(mosquitto)
# The TLS test makes its certificates with openssl.
command -v openssl >/dev/null 2>&1 || need+=(openssl)
if ((${#need[@]})); then
  if command -v apt-get >/dev/null 2>&1 && { [[ $(id -u) == 0 ]] || sudo -n true 2>/dev/null; }; then
    echo "scripts/test.sh: installing ${need[*]}"
    "${as_root[@]}" apt-get update -qq >/dev/null || true
    "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need[@]}" >/dev/null \
      || echo "scripts/test.sh: could not install ${need[*]}; the tests that need them will skip"
  else
    echo "scripts/test.sh: ${need[*]} missing and no way to install; the tests that need them will skip"
  fi
fi

# The OPC UA server is tested against an independent client, python asyncua, installed here into
# a virtual environment under target/ (never into the system's python) and found by the test
# through PLC_OPCUA_PYTHON.
asyncua_version=2.1.0
venv=target/opcua-venv
if ! "$venv/bin/python" -c "import asyncua, sys; sys.exit(asyncua.__version__ != '$asyncua_version')" 2>/dev/null; then
  echo "scripts/test.sh: installing python asyncua $asyncua_version into $venv"
  if ! python3 -m venv "$venv" >/dev/null 2>&1; then
    command -v apt-get >/dev/null 2>&1 && { [[ $(id -u) == 0 ]] || sudo -n true 2>/dev/null; } \
      && "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq python3-venv >/dev/null
    python3 -m venv "$venv"
  fi
  "$venv/bin/pip" install -q --disable-pip-version-check "asyncua==$asyncua_version"
fi
export PLC_OPCUA_PYTHON="$PWD/$venv/bin/python"

# The Sparkplug B edge node is tested against an independent host: pysparkplug (on paho-mqtt),
# in a virtual environment of its own under target/, found by the test through
# PLC_SPARKPLUG_PYTHON.
pysparkplug_version=0.6.1
spb_venv=target/sparkplug-venv
if ! "$spb_venv/bin/python" -c "import pysparkplug, sys; sys.exit(pysparkplug.__version__ != '$pysparkplug_version')" 2>/dev/null; then
  echo "scripts/test.sh: installing python pysparkplug $pysparkplug_version into $spb_venv"
  python3 -m venv "$spb_venv"
  "$spb_venv/bin/pip" install -q --disable-pip-version-check "pysparkplug==$pysparkplug_version"
fi
export PLC_SPARKPLUG_PYTHON="$PWD/$spb_venv/bin/python"

# The loader's tests load real program modules: cargo builds a `cdylib` only when asked.
cargo build -p plc-test-module-counter -p plc-test-module-counter-v2 -p plc-test-module-panics -p plc-test-module-foreign -p tensile-tester-module -p new-program -p plc-module

cargo test --workspace "$@"
