#!/usr/bin/env bash
# Issue 16, "an independent secure peer": Cyclone DDS 0.10.2 from Debian's packages (libddsc0debian with
# its DDS Security plugins, cyclonedds-dev, cyclonedds-tools' idlc) publishes ergocell_msgs/
# CameraLandmarks into a secured `ergocell run`, in a private network namespace on loopback. The peer's
# messages carry camera_id "cyclone_probe", which run counts as rejected (no such camera in the rig): the
# count would prove they arrived. Cases (run secured with the cell enclave each time):
#   peer with the s1_left camera's enclave, on s1_left's topic   Cyclone accepts ergocell's keystore and
#       the PKI-DH authentication with RustDDS completes (after two RustDDS fixes, ERGOCELL-PATCH.md);
#       KNOWN GAP, reported not failed: Cyclone then refuses RustDDS's crypto tokens ("Invalid Crypto
#       token"), so no sample arrives. The script says so if that ever changes.
#   peer unsecured                                              nothing received
#   peer with another CA's keystore                             nothing received
#   peer with the s1_left enclave, on s2_left's topic           Cyclone refuses the topic itself
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
xml "" "$tmp/open.xml"
xml "$tmp/foreign/$cam" "$tmp/foreign.xml"
cp .ci/interop/sros2.sh "$tmp/" 2>/dev/null || true

unshare -n -- bash -s "$bin" "$tmp" <<'NS'
set -euo pipefail
bin=$1 tmp=$2
ip link set lo up
ip link set lo multicast on
case_() {  # case_ <label> <cyclone xml> <dds topic>
  RUST_LOG="${RUST_LOG:-}" timeout -k 5 60 "$bin" --log "${RUN_LOG:-warn}" run --config config/cell.toml --trajectories trajectories --max-secs 14 \
    --keystore "$tmp/ks" > "$tmp/$1.run" 2>&1 &
  local run=$!
  sleep 2
  CYCLONEDDS_URI="file://$2" timeout -k 5 40 "$tmp/peer" "$3" cyclone_probe 8 > "$tmp/$1.peer" 2>&1 \
    || echo "peer exit $?" >> "$tmp/$1.peer"
  wait "$run" || true
}
case_ secure "$tmp/camera.xml" rt/ergocell/camera/s1_left/landmarks
case_ open "$tmp/open.xml" rt/ergocell/camera/s1_left/landmarks
case_ foreign "$tmp/foreign.xml" rt/ergocell/camera/s1_left/landmarks
case_ other "$tmp/camera.xml" rt/ergocell/camera/s2_left/landmarks
NS

python3 - "$tmp" <<'PY'
import re, sys
t = sys.argv[1]
fail = []
def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        fail.append(what)
read = lambda n: open(f"{t}/{n}").read()
def rejected(n):
    m = re.search(r"(\d+) camera message\(s\) rejected", read(n + ".run"))
    return int(m.group(1)) if m else -1
for n in ["secure", "open", "foreign", "other"]:
    print(f"{n}: peer says {read(n + '.peer').strip()!r}; run counted {rejected(n)} of its messages")
sr, sp = read("secure.run"), read("secure.peer")
check("published" in sp and "participant refused" not in sp,
      "Cyclone DDS accepts ergocell's keystore (identity, signed governance and permissions)")
check("handshake" not in sr.lower() or "failed" not in " ".join(l for l in sr.lower().splitlines() if "handshake" in l),
      "the PKI-DH authentication handshake between Cyclone and RustDDS completes (no handshake failure)")
if rejected("secure") > 0:
    print("ok   Cyclone DDS → secured run: the s1_left camera's messages arrived (the known crypto-token gap is gone: update README)")
elif "Invalid Crypto token" in sp:
    print("KNOWN GAP Cyclone DDS → secured run: no sample arrives; Cyclone refuses RustDDS's crypto tokens:")
    print("          " + next(l for l in sp.splitlines() if "Invalid Crypto token" in l)[:220])
else:
    check(False, "Cyclone DDS → secured run: neither arrived nor the known crypto-token refusal")
check(rejected("open") == 0, "an unsecured Cyclone participant's messages never reach the secured run")
check(rejected("foreign") == 0, "a Cyclone participant with another CA's certificate is not matched")
check(rejected("other") == 0 and ("writer refused" in read("other.peer") or "topic refused: Not Allowed By Security" in read("other.peer")),
      "the s1_left enclave cannot publish on s2_left's topic (Cyclone refuses it: Not Allowed By Security)")
if fail:
    for n in ["secure.run", "secure.peer"]:
        print(f"--- {n}\n" + read(n)[-2500:])
sys.exit(1 if fail else 0)
PY
