# Sourced by the interop stages: a copy of the cell in "$tmp" with c2 locked and approved for this
# test only (never trajectories/approvals/). A throwaway approver key made here by ssh-keygen is the
# one the approvers' file trusts, under a throwaway site approvers authority installed in a
# root-owned anchor folder ("$tmp/anchor": mktemp's folder, 0700, under the sticky /tmp), as an
# integrator installs /etc/ergocell; ERGOCELL_TRUST_ANCHOR_DIR is exported for the cell's commands.
# Needs: $bin, $tmp, $who (the approver's principal).
mkdir -p "$tmp/traj" "$tmp/cell" "$tmp/anchor"
cp -r config/. "$tmp/cell/"
cp trajectories/c*.toml trajectories/handover_rula.toml "$tmp/traj/"
ssh-keygen -q -t ed25519 -N "" -C "ergocell $who test key (not a sign-off)" -f "$tmp/key"
ssh-keygen -q -t ed25519 -N "" -C "throwaway site approvers authority" -f "$tmp/site"
install -m 0644 "$tmp/site.pub" "$tmp/anchor/approvers-authority.pub"
export ERGOCELL_TRUST_ANCHOR_DIR="$tmp/anchor"
printf '%s namespaces="ergocell-trajectory-approval" %s\n' "$who" "$(cat "$tmp/key.pub")" \
  > "$tmp/cell/approvers/allowed_signers"
# The authority signs the approvers' files with ssh-keygen, as a site would with its offline key.
"$bin" trajectories --cell "$tmp/cell/cell.toml" --trajectories-dir "$tmp/traj" approvers-message \
  > "$tmp/approvers.msg"
ssh-keygen -q -Y sign -f "$tmp/site" -n ergocell-approvers "$tmp/approvers.msg"
"$bin" trajectories --cell "$tmp/cell/cell.toml" --trajectories-dir "$tmp/traj" sign-approvers \
  --signed "$tmp/approvers.msg.sig" > /dev/null
"$bin" trajectories --cell "$tmp/cell/cell.toml" --trajectories-dir "$tmp/traj" lock --class c2 > /dev/null
"$bin" trajectories --cell "$tmp/cell/cell.toml" --trajectories-dir "$tmp/traj" approve --class c2 \
  --by "$who" --key "$tmp/key" > /dev/null
