#!/usr/bin/env bash
# Multi-host MPI on one machine: two Linux network namespaces stand for two hosts, each with its
# own address on a veth pair (10.199.77.1 and .2/24) and its own host name (a UTS namespace).
# Open MPI starts in host 1 and reaches host 2 through a launch agent (plm_rsh_agent, in place of
# ssh) that enters host 2's namespaces; the hostfile names the hosts by address; the ranks talk
# over TCP on the veth subnet only (pml ob1, btl tcp,self, btl/oob_tcp_if_include), so no shared
# memory joins the hosts. Checked: the ranks sit on both hosts (their host names), and the coarse
# 2D two-phase dam break (40 steps) and the coarse 3D two-phase dam break (20 steps, also
# re-partitioned) on 2 hosts x 1 rank and 2 hosts x 2 ranks give particle data bitwise identical
# to the one-host, one-rank run, with the particle data crossing the veth (its byte counters).
# Needs root and iproute2 (`ip netns`); otherwise prints "SKIPPED: reason" and exits 0. The
# namespaces are removed on exit, also on failure. `make test-multihost` runs it.
set -eu
cd "$(dirname "$0")/../.."
PYTHON=${PYTHON:-/usr/bin/python3}
skip() { echo "SKIPPED: $*"; exit 0; }
[ "$(id -u)" -eq 0 ] || skip "needs root to create network namespaces"
command -v ip >/dev/null || skip "no 'ip' command (iproute2)"
command -v unshare >/dev/null || skip "no 'unshare' command (util-linux)"

subnet=10.199.77.0/24
tag=mpsph$$
ns=("$tag-h1" "$tag-h2")
addr=(10.199.77.1 10.199.77.2)
dev=("${tag}a" "${tag}b")   # the veth ends, one in each namespace
out=$(mktemp -d)
cleanup() {
  ip netns delete "${ns[0]}" 2>/dev/null || true
  ip netns delete "${ns[1]}" 2>/dev/null || true   # removing a namespace removes its veth end
  ip link delete "${dev[0]}" 2>/dev/null || true    # a veth not yet moved into its namespace
  rm -rf "$out"
}
trap cleanup EXIT
trap "exit 1" INT TERM HUP

ip netns add "${ns[0]}" 2>/dev/null || skip "cannot create a network namespace (ip netns add)"
ip netns add "${ns[1]}"
ip link add "${dev[0]}" type veth peer name "${dev[1]}" 2>/dev/null || skip "cannot create a veth pair"
for i in 0 1; do
  ip link set "${dev[$i]}" netns "${ns[$i]}"
  ip -n "${ns[$i]}" addr add "${addr[$i]}/24" dev "${dev[$i]}"
  ip -n "${ns[$i]}" link set "${dev[$i]}" up
  ip -n "${ns[$i]}" link set lo up
done
ip netns exec "${ns[0]}" unshare --uts true 2>/dev/null || skip "cannot create a UTS namespace (unshare --uts)"

# The launch agent: `agent ADDRESS COMMAND...` runs COMMAND (joined into one shell command line,
# as ssh does) in the namespaces of the host with that address, under the host name mh-hostN.
agent=$out/agent
cat > "$agent" <<EOF
#!/bin/sh
case "\$1" in
  ${addr[0]}) net=${ns[0]} name=mh-host1 ;;
  ${addr[1]}) net=${ns[1]} name=mh-host2 ;;
  *) echo "agent: unknown host '\$1'" >&2; exit 1 ;;
esac
shift
exec ip netns exec "\$net" unshare --uts /bin/sh -c 'hostname "\$0" && exec /bin/sh -c "\$1"' "\$name" "\$*"
EOF
chmod +x "$agent"

# mpirun_hosts RANKS_PER_HOST COMMAND...: mpirun started on host 1, ranks 0.. on host 1, the rest
# on host 2.
mpirun_hosts() {
  local per=$1
  shift
  printf '%s slots=%d\n' "${addr[0]}" "$per" "${addr[1]}" "$per" > "$out/hostfile"
  "$agent" "${addr[0]}" "$(printf '%q ' mpirun --allow-run-as-root -n $((2 * per)) \
    --hostfile "$out/hostfile" --mca plm_rsh_agent "$agent" --mca pml ob1 --mca btl tcp,self \
    --mca btl_tcp_if_include "$subnet" --mca oob_tcp_if_include "$subnet" "$@")"
}
rx_bytes() { ip netns exec "${ns[1]}" cat "/sys/class/net/${dev[1]}/statistics/rx_bytes"; }

# The ranks are placed on both hosts.
mpirun_hosts 2 sh -c 'echo "$OMPI_COMM_WORLD_RANK $(hostname)"' | sort > "$out/placement"
printf '0 mh-host1\n1 mh-host1\n2 mh-host2\n3 mh-host2\n' | diff - "$out/placement"

# logged LOG COMMAND...: COMMAND with its output into LOG, shown if it fails.
logged() {
  local log=$1
  shift
  "$@" > "$log" 2>&1 || { cat "$log"; return 1; }
}

# check NAME CASE STEPS [--set ...]: the one-rank run of CASE on this host against 2 hosts x 1
# and 2 hosts x 2 ranks; the extra arguments go to the multi-host runs only.
check() {
  local name=$1 case=$2 steps=$3
  shift 3
  local args=(build/mpsph run "$case" --set time.max_steps="$steps")
  logged "$out/$name-1host.log" scripts/mpirun -n 1 "${args[@]}" -o "$out/$name-1host"
  for per in 1 2; do
    local run=$out/$name-2x$per before received
    before=$(rx_bytes)
    logged "$run.log" mpirun_hosts "$per" "${args[@]}" -o "$run" "$@"
    received=$(( $(rx_bytes) - before ))
    echo "$name on 2 hosts x $per: host 2 received $received bytes over the veth"
    # the launch alone moves a few kB (about 2.3 kB for the placement run above); the halo
    # exchanges of these runs move over 10 MB
    [ "$received" -gt 1000000 ] || { echo "too little traffic between the hosts"; return 1; }
    "$PYTHON" tests/compare_snapshots.py "$out/$name-1host" "$run"
  done
}
check 2d tests/cases/dambreak-2phase-coarse.yaml 40
check 3d tests/cases/dambreak-3d-2phase.yaml 20 --set parallel.repartition_every=7
