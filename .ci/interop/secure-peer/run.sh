#!/usr/bin/env bash
# Issue 16, "an independent secure peer": Cyclone DDS 0.10.2 from Debian's packages (libddsc0debian with
# its DDS Security plugins, cyclonedds-dev, cyclonedds-tools' idlc) publishes ergocell_msgs/
# CameraLandmarks into a secured `ergocell run`, in a private network namespace on loopback, with a
# packet sniffer on loopback. The peer's messages carry camera_id "cyclone_probe", which run counts as
# rejected (no such camera in the rig): the count proves they arrived. Cases (run secured with the
# cell enclave each time):
#   peer with the s1_left camera's enclave, on s1_left's topic   the messages arrive; no data packet
#       carries the camera id in the clear (after three RustDDS fixes, vendor/rustdds/ERGOCELL-PATCH.md)
#   peer unsecured                                              nothing received
#   peer with another CA's keystore                             nothing received
#   peer with the s1_left enclave, on s2_left's topic           Cyclone refuses the topic itself
#   s1_left's identity with permissions for every camera,       Cyclone publishes (its own checks pass);
#       signed by a permissions CA of the peer's own, on        ergocell's run refuses permissions its
#       s2_left's topic                                         permissions CA did not sign: nothing received
#   both unsecured (run without a keystore)                     the control: the messages arrive and the
#                                                               sniffer sees the camera id in their packets
# Usage: .ci/interop/secure-peer/run.sh target/release/ergocell
set -euo pipefail
cd "$(dirname "$0")/../../.."
bin=$(realpath "${1:-target/release/ergocell}")
tmp=$(mktemp -d)
trap 'if [ -n "${KEEP_LOGS:-}" ]; then cp "$tmp"/*.run "$tmp"/*.peer "$KEEP_LOGS"/ 2>/dev/null; fi; rm -rf "$tmp"' EXIT
plugins=/usr/lib/x86_64-linux-gnu/libddsc0debian
idlc -o "$tmp" .ci/interop/secure-peer/CameraLandmarks.idl 2>/dev/null
gcc -O1 -o "$tmp/peer" .ci/interop/secure-peer/peer.c "$tmp/CameraLandmarks.c" -I"$tmp" -lddsc
"$bin" security create-keystore --keystore "$tmp/ks" > /dev/null
"$bin" security create-keystore --keystore "$tmp/foreign" > /dev/null
xml() {  # xml <enclave dir or ""> <out>
  local sec=""
  if [ -n "$1" ]; then
    sec="<Security>
      <Authentication>
        <Library path=\"$plugins/libdds_security_auth.so\" initFunction=\"init_authentication\" finalizeFunction=\"finalize_authentication\"/>
        <IdentityCA>file:$1/identity_ca.cert.pem</IdentityCA>
        <IdentityCertificate>file:$1/cert.pem</IdentityCertificate>
        <PrivateKey>file:$1/key.pem</PrivateKey>
      </Authentication>
      <AccessControl>
        <Library path=\"$plugins/libdds_security_ac.so\" initFunction=\"init_access_control\" finalizeFunction=\"finalize_access_control\"/>
        <PermissionsCA>file:$1/permissions_ca.cert.pem</PermissionsCA>
        <Governance>file:$1/governance.p7s</Governance>
        <Permissions>file:$1/permissions.p7s</Permissions>
      </AccessControl>
      <Cryptographic>
        <Library path=\"$plugins/libdds_security_crypto.so\" initFunction=\"init_crypto\" finalizeFunction=\"finalize_crypto\"/>
      </Cryptographic>
    </Security>"
  fi
  cat > "$2" <<XML
<CycloneDDS xmlns="https://cdds.io/config"><Domain Id="any">
  <General><Interfaces><NetworkInterface name="lo"/></Interfaces><AllowMulticast>false</AllowMulticast></General>
  <Discovery><ParticipantIndex>auto</ParticipantIndex><MaxAutoParticipantIndex>20</MaxAutoParticipantIndex>
    <Peers><Peer Address="127.0.0.1"/></Peers></Discovery>
  $sec
</Domain></CycloneDDS>
XML
}
cam=enclaves/ergocell/camera/s1_left
xml "$tmp/ks/$cam" "$tmp/camera.xml"
# The liar: s1_left's own identity (certificate and key from the cell's identity CA), but
# permissions rewritten to allow every camera's topic and signed by a permissions CA of its own (the
# foreign keystore's), which its Cyclone is told to trust, with a governance signed by that CA too.
# Its own checks pass; ergocell's run must refuse permissions its permissions CA did not sign.
cp -r "$tmp/ks/$cam" "$tmp/liar"
sed -e 's|<topic>rt/ergocell/camera/s1_left/landmarks</topic>|<topic>rt/ergocell/camera/*/landmarks</topic>|' \
    "$tmp/ks/$cam/permissions.xml" > "$tmp/liar/permissions.xml"
grep -q 'camera/\*/landmarks' "$tmp/liar/permissions.xml"
openssl smime -sign -text -in "$tmp/liar/permissions.xml" -out "$tmp/liar/permissions.p7s" \
  -signer "$tmp/foreign/public/permissions_ca.cert.pem" -inkey "$tmp/foreign/private/permissions_ca.key.pem"
cp "$tmp/foreign/public/permissions_ca.cert.pem" "$tmp/liar/permissions_ca.cert.pem"
cp "$tmp/foreign/enclaves/governance.p7s" "$tmp/liar/governance.p7s"
xml "$tmp/liar" "$tmp/liar.xml"
cat > "$tmp/sniff.py" <<'PY'
# Counts UDP packets on lo carrying RTPS, and whether the peer's camera id appears in them in the
# clear, for `secs` seconds, apart for user traffic (odd RTPS ports) and metatraffic (even).
import json, socket, sys, time
secs, out = float(sys.argv[1]), sys.argv[2]
s = socket.socket(socket.AF_PACKET, socket.SOCK_RAW, socket.ntohs(0x0003))
s.bind(("lo", 0))
s.settimeout(0.2)
packets, clear = {"user": 0, "meta": 0}, {"user": 0, "meta": 0}
end = time.time() + secs
while time.time() < end:
    try:
        frame = s.recv(65535)
    except socket.timeout:
        continue
    if len(frame) > 42 and frame[12:14] == b"\x08\x00" and frame[23] == 17 and frame[42:46] == b"RTPS":
        kind = "user" if int.from_bytes(frame[36:38], "big") % 2 else "meta"
        packets[kind] += 1
        clear[kind] += b"cyclone_probe" in frame[42:]
json.dump({"packets": packets, "cyclone_probe_in_clear": clear}, open(out, "w"))
PY
xml "" "$tmp/open.xml"
xml "$tmp/foreign/$cam" "$tmp/foreign.xml"
cp .ci/interop/sros2.sh "$tmp/" 2>/dev/null || true

unshare -n -- bash -s "$bin" "$tmp" <<'NS'
set -euo pipefail
bin=$1 tmp=$2
ip link set lo up
ip link set lo multicast on
case_() {  # case_ <label> <cyclone xml> <dds topic> [run unsecured]
  python3 "$tmp/sniff.py" 16 "$tmp/$1.sniff" &
  local sniff=$!
  local secured=(--keystore "$tmp/ks")
  if [ -n "${4:-}" ]; then secured=(); fi
  RUST_LOG="${RUST_LOG:-}" timeout -k 5 60 "$bin" --log "${RUN_LOG:-warn}" run --config config/cell.toml --trajectories trajectories --max-secs 14 \
    "${secured[@]}" > "$tmp/$1.run" 2>&1 &
  local run=$!
  sleep 2
  CYCLONEDDS_URI="file://$2" timeout -k 5 40 "$tmp/peer" "$3" cyclone_probe 8 > "$tmp/$1.peer" 2>&1 \
    || echo "peer exit $?" >> "$tmp/$1.peer"
  wait "$run" || echo "run exit $?" >> "$tmp/$1.run"
  wait "$sniff"
}
case_ secure "$tmp/camera.xml" rt/ergocell/camera/s1_left/landmarks
case_ open "$tmp/open.xml" rt/ergocell/camera/s1_left/landmarks
case_ foreign "$tmp/foreign.xml" rt/ergocell/camera/s1_left/landmarks
case_ other "$tmp/camera.xml" rt/ergocell/camera/s2_left/landmarks
# RustDDS's own verdict on the peer's permissions is logged at info by its secure discovery.
RUN_LOG="warn,rustdds::discovery::secure_discovery=info" case_ liar "$tmp/liar.xml" rt/ergocell/camera/s2_left/landmarks
case_ plain "$tmp/open.xml" rt/ergocell/camera/s1_left/landmarks unsecured
NS

python3 - "$tmp" <<'PY'
import json, re, sys
t = sys.argv[1]
fail = []
def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        fail.append(what)
read = lambda n: open(f"{t}/{n}").read()
sniff = lambda n: json.load(open(f"{t}/{n}.sniff"))
def rejected(n):
    m = re.search(r"(\d+) camera message\(s\) rejected", read(n + ".run"))
    return int(m.group(1)) if m else -1
for n in ["secure", "open", "foreign", "other", "liar", "plain"]:
    print(f"{n}: peer says {read(n + '.peer').strip()!r}; run counted {rejected(n)} of its messages; "
          f"sniffer {sniff(n)}")
# A run that did not end by itself (timeout's 124, or 137 after its SIGKILL) is reported with its
# log's end (a RustDDS lock-order inversion hung a run this way in CI, twice; fixed in the vendored
# copy, vendor/rustdds/ERGOCELL-PATCH.md, seventh fix).
for n in ["secure", "open", "foreign", "other", "liar", "plain"]:
    m = re.search(r"run exit (\d+)", read(n + ".run"))
    if m and m.group(1) in ("124", "137"):
        print(f"NOTE {n}: run did not end by itself within 60 s (exit {m.group(1)}); the end of its log:")
        print("     " + "\n     ".join(read(n + ".run").splitlines()[-6:])[:1500])
sr, sp = read("secure.run"), read("secure.peer")
check("published" in sp and "participant refused" not in sp,
      "Cyclone DDS accepts ergocell's keystore (identity, signed governance and permissions)")
check("handshake" not in sr.lower() or "failed" not in " ".join(l for l in sr.lower().splitlines() if "handshake" in l),
      "the PKI-DH authentication handshake between Cyclone and RustDDS completes (no handshake failure)")
sent = int(re.search(r"published (\d+)", sp).group(1)) if "published" in sp else 0
check(rejected("secure") >= 60 and "Invalid Crypto token" not in sp,
      f"Cyclone DDS → secured run: the s1_left camera's messages arrive ({rejected('secure')} of {sent}; "
      "Cyclone accepts RustDDS's crypto tokens)")
s = sniff("secure")
check(s["packets"]["user"] >= 60 and s["cyclone_probe_in_clear"]["user"] == 0
      and s["cyclone_probe_in_clear"]["meta"] == 0,
      f"…encrypted: the camera id in none of {s['packets']['user']} data and {s['packets']['meta']} discovery packets")
o = sniff("plain")
check(rejected("plain") > 0 and o["cyclone_probe_in_clear"]["user"] > 0,
      f"control: both unsecured, the peer's messages arrive ({rejected('plain')}) with its camera id in plain "
      f"sight in {o['cyclone_probe_in_clear']['user']} data packets")
check(rejected("open") == 0, "an unsecured Cyclone participant's messages never reach the secured run")
check(rejected("foreign") == 0, "a Cyclone participant with another CA's certificate is not matched")
check(rejected("other") <= 0 and ("writer refused" in read("other.peer") or "topic refused: Not Allowed By Security" in read("other.peer")),
      "the s1_left enclave cannot publish on s2_left's topic (Cyclone refuses it: Not Allowed By Security)")
lp = read("liar.peer")
verdict = next((l for l in read("liar.run").splitlines() if "Validating permissions for remote failed" in l), "")
print("liar: ergocell's run says: " + verdict[verdict.find("Validating"):][:200])
check("published" in lp and rejected("liar") == 0 and verdict != "",
      "a peer with s1_left's identity and self-signed permissions for every camera's topic publishes on "
      "s2_left's, and the secured run refuses it: run rejects permissions its permissions CA did not sign")
if fail:
    for n in ["secure.run", "secure.peer", "liar.run", "liar.peer"]:
        print(f"--- {n}\n" + read(n)[-2500:])
sys.exit(1 if fail else 0)
PY
