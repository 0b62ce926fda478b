#!/usr/bin/env bash
# Issue 16, SROS2 (DDS Security) between ergocell's own nodes, RustDDS at both ends: `ergocell replay
# --ros` publishes a recorded session's camera landmarks, `ergocell run` fuses them. In a private network
# namespace (loopback with multicast), each case 20 s, with a packet sniffer on loopback:
#   both secured, one keystore            the session is fused and classed; the sniffer finds no camera id
#                                          or topic name in any data packet and no type name in discovery
#                                          (enclave names and permissions are public in the handshake, as
#                                          DDS Security 1.1 specifies)
#   both unsecured                         the control: the sniffer sees the camera ids in the data
#   replay unsecured                       run (secured) fuses nothing
#   replay with another CA's keystore      run fuses nothing (not authenticated, not matched)
#   replay as the s1_left camera           refused locally: that enclave may publish s1_left only
#   [ros] security_required, no keystore   run refuses to start
# Usage: .ci/interop/sros2.sh target/release/ergocell
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=$(realpath "${1:-target/release/ergocell}")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bin" --log error demo --cycles 1 --fps 30 --stature-m 1.815 --no-faults --out "$tmp/session.mcap" > /dev/null
"$bin" security create-keystore --keystore "$tmp/ks" > "$tmp/ks.log"
"$bin" security create-keystore --keystore "$tmp/foreign" > /dev/null
cp -r config "$tmp/required"
python3 - "$tmp/required/cell.toml" <<'PY'
import sys
p = sys.argv[1]
s = open(p).read()
assert "\nsecurity_required = false\n" in s
open(p, "w").write(s.replace("\nsecurity_required = false\n", "\nsecurity_required = true\n", 1))
PY
cat > "$tmp/sniff.py" <<'PY'
# Counts UDP packets on lo and which plaintext markers appear in them, for `secs` seconds, apart for
# user traffic (RTPS user ports: odd on domain 0, 7401 and 7411 + 2i) and metatraffic (discovery: even).
import json, socket, sys, time
secs, out = float(sys.argv[1]), sys.argv[2]
markers = [b"landmarks", b"s1_left", b"ergocell", b"CameraLandmarks"]
s = socket.socket(socket.AF_PACKET, socket.SOCK_RAW, socket.ntohs(0x0003))
s.bind(("lo", 0))
s.settimeout(0.2)
seen = {"user": set(), "meta": set()}
packets = {"user": 0, "meta": 0}
end = time.time() + secs
while time.time() < end:
    try:
        frame = s.recv(65535)
    except socket.timeout:
        continue
    if len(frame) > 42 and frame[12:14] == b"\x08\x00" and frame[23] == 17 and frame[42:46] == b"RTPS":
        kind = "user" if int.from_bytes(frame[36:38], "big") % 2 else "meta"
        packets[kind] += 1
        for m in markers:
            if m in frame[42:]:
                seen[kind].add(m.decode())
json.dump({"packets": packets, "plaintext": {k: sorted(v) for k, v in seen.items()}}, open(out, "w"))
PY

unshare -n -- bash -s "$bin" "$tmp" <<'NS'
set -euo pipefail
bin=$1 tmp=$2
ip link set lo up
ip link set lo multicast on
ip route add 224.0.0.0/4 dev lo
case_() {  # case_ <label> <run args...> -- <replay args...>
  local label=$1; shift
  local run_args=() replay_args=()
  while [ "$1" != "--" ]; do run_args+=("$1"); shift; done; shift
  replay_args=("$@")
  python3 "$tmp/sniff.py" 22 "$tmp/$label.sniff" &
  local sniff=$!
  timeout -k 5 60 "$bin" --log error run --config config/cell.toml --trajectories trajectories --max-secs 20 \
    "${run_args[@]}" > "$tmp/$label.run" 2>&1 &
  local run=$!
  sleep 2
  # A replay whose samples no one may read can block in the DDS writer: 40 s at most.
  timeout -s INT -k 5 40 "$bin" --log error replay "$tmp/session.mcap" --ros --speed 4 "${replay_args[@]}" \
    > "$tmp/$label.replay" 2>&1 || echo "replay exit $?" >> "$tmp/$label.replay"
  wait "$run" || true
  wait "$sniff"
}
case_ secure --keystore "$tmp/ks" -- --keystore "$tmp/ks"
case_ plain --
case_ open --keystore "$tmp/ks" --
case_ foreign --keystore "$tmp/ks" -- --keystore "$tmp/foreign"
env ROS_SECURITY_ENCLAVE_OVERRIDE=/ergocell/camera/s1_left \
  timeout -s INT -k 5 40 "$bin" --log error replay "$tmp/session.mcap" --ros --speed 4 --keystore "$tmp/ks" \
  > "$tmp/camera.replay" 2>&1 || echo "replay exit $?" >> "$tmp/camera.replay"
timeout -k 5 40 "$bin" --log error run --config "$tmp/required/cell.toml" --trajectories trajectories --max-secs 5 \
  > "$tmp/required.run" 2>&1 || echo "run exit $?" >> "$tmp/required.run"
NS

python3 - "$tmp" <<'PY'
import json, sys
t = sys.argv[1]
fail = []
def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        fail.append(what)
read = lambda n: open(f"{t}/{n}").read()
sniff = lambda n: json.load(open(f"{t}/{n}.sniff"))
s = sniff("secure")
print(f"secured: RTPS packets {s['packets']}, plaintext markers seen {s['plaintext']}")
check("DDS Security on: enclave /ergocell/cell" in read("secure.run"), "run started secured (enclave /ergocell/cell)")
check("height measured" in read("secure.run") and "class c2" in read("secure.run"),
      "secured replay → secured run: the session was fused and classed c2")
check(s["packets"]["user"] > 100 and not s["plaintext"]["user"],
      "no camera id or topic name in any data packet: the landmarks went encrypted")
check("CameraLandmarks" not in s["plaintext"]["meta"],
      "no message type name in discovery: endpoints announced encrypted (type names appear nowhere else)")
print("note: in the clear by DDS Security's design: each participant's certificate subject (its enclave name, "
      f"in SPDP) and its signed permissions (the topics it may use) in the authentication handshake: {s['plaintext']['meta']}")
p = sniff("plain")
print(f"unsecured run and replay: RTPS packets {p['packets']}, plaintext markers seen {p['plaintext']}")
check("height measured" in read("plain.run") and "s1_left" in p["plaintext"]["user"],
      "control: unsecured, the same session's camera ids are in plain sight in the data packets")
o = sniff("open")
print(f"unsecured replay: RTPS packets {o['packets']}, plaintext markers seen {o['plaintext']}")
check("height measured" not in read("open.run"), "an unsecured participant's landmarks never reach the secured run")

check("height measured" not in read("foreign.run"), "a participant with another CA's certificate is not matched")
c = read("camera.replay")
check("Not allowed to create the topic rt/ergocell/camera/" in c and "replay exit" in c and "s1_left/landmarks" not in c.split("Not allowed")[1][:60],
      "the s1_left camera's enclave cannot publish the other cameras' topics")
r = read("required.run")
check("requires DDS Security" in r and "run exit" in r, "security_required without a keystore: run refuses to start")
if fail:
    for n in ["secure.run", "secure.replay", "open.run", "foreign.run", "camera.replay", "required.run"]:
        print(f"--- {n}\n" + read(n)[-1500:])
sys.exit(1 if fail else 0)
PY
