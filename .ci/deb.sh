#!/usr/bin/env bash
# The cell PC's Debian package: `cargo deb --no-build` packages the release build (the binary, the
# systemd unit, the reference cell as a site-folder template, the user pages; Cargo.toml's
# [package.metadata.deb]). Checks the package's dependencies and files, then runs the packaged
# binary from another directory: installed with dpkg where this is CI (a throwaway machine, as root),
# else unpacked with dpkg-deb -x (no change to a developer's system).
#   .ci/deb.sh            after `cargo build --release --locked -p ergocell`
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# cargo-deb 3.8.0: its own lock file (--locked), built once into a temporary root.
cargo install cargo-deb --version 3.8.0 --locked --quiet --root "$work/cargo-deb"
"$work/cargo-deb/bin/cargo-deb" --no-build --quiet -o "$work/out/" >/dev/null
deb=$(ls "$work"/out/ergocell_*.deb)
echo "built $(basename "$deb") ($(( $(stat -c %s "$deb") / 1000000 )) MB)"

fail() { echo "deb: $*" >&2; exit 1; }
control=$(dpkg-deb -f "$deb" Depends)
case "$control" in *libssl3*) ;; *) fail "Depends does not name libssl3: $control" ;; esac
files=$(dpkg-deb -c "$deb" | awk '{print $6}')
for f in ./usr/bin/ergocell ./lib/systemd/system/ergocell.service \
    ./usr/share/ergocell/config/cell.toml ./usr/share/ergocell/config/robots/iiwa14_r820.urdf \
    ./usr/share/ergocell/trajectories/locks/c2.lock.toml ./usr/share/doc/ergocell/integrator.md; do
  grep -qxF "$f" <<<"$files" || fail "the package lacks $f"
done
if command -v systemd-analyze >/dev/null; then
  dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$work" ./lib/systemd/system/ergocell.service
  # verify resolves ExecStart's /bin/sh; the unit's `exec ergocell` is found on systemd's PATH.
  systemd-analyze verify "$work/lib/systemd/system/ergocell.service"
fi

run_dir=$(mktemp -d -p "$work")
if [ -n "${CI:-}" ] && [ "$(id -u)" = 0 ]; then
  DEBIAN_FRONTEND=noninteractive dpkg -i "$deb" >/dev/null
  bin=/usr/bin/ergocell
  getent passwd ergocell >/dev/null || fail "postinst did not create the ergocell account"
  [ -d /var/lib/ergocell ] || fail "postinst did not create /var/lib/ergocell"
else
  dpkg-deb -x "$deb" "$work/root"
  bin=$work/root/usr/bin/ergocell
fi
(cd "$run_dir" && "$bin" --version && "$bin" demo >demo.txt \
  && "$bin" report ergocell-demo.mcap --out report.html >/dev/null && test -s report.html \
  && tail -1 demo.txt)
if [ "$bin" = /usr/bin/ergocell ]; then
  touch /var/lib/ergocell/keep-me
  dpkg -r ergocell >/dev/null
  [ ! -e /usr/bin/ergocell ] || fail "dpkg -r left /usr/bin/ergocell"
  [ -e /var/lib/ergocell/keep-me ] || fail "removing the package removed the state folder"
  rm -f /var/lib/ergocell/keep-me
fi
echo "deb: the packaged ergocell runs demo and report from another directory"
