#!/usr/bin/env bash
# `lbdem sweep --slurm` on a real single-node SLURM: installs slurm (Debian's slurmctld, slurmd,
# slurm-client) and munge when missing (as root, with apt-get), starts munged, slurmctld and
# slurmd with a slurm.conf of this node written into a temporary folder, submits a 4-task sweep
# (2 tiny dry cases x 2 packing seeds), waits for it, gathers the report with --report and checks
# it; the daemons are stopped at the end, also on failure. Exits 77 (skipped) when SLURM cannot be
# installed or started here.
# Usage: SweepSlurm.sh LBDEM SWEEP_FILE OUT_DIR
set -euo pipefail
lbdem=$1 sweep=$2 out=$3
skip() { echo "SKIPPED: $*"; exit 77; }
fail() { echo "FAILED: $*"; exit 1; }

if ! command -v slurmctld >/dev/null || ! command -v slurmd >/dev/null || ! command -v sbatch >/dev/null ||
    ! command -v munged >/dev/null; then
    [[ $(id -u) == 0 ]] && command -v apt-get >/dev/null || skip "SLURM is not installed and this is not root with apt-get"
    echo "installing slurmctld slurmd slurm-client munge with apt-get"
    install() { DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends slurmctld slurmd slurm-client munge; }
    # A machine whose package lists are empty needs an update first.
    install >/dev/null 2>&1 || { apt-get update -qq >/dev/null 2>&1 && install >/dev/null 2>&1; } ||
        skip "apt-get could not install slurmctld slurmd slurm-client munge"
fi
[[ $(id -u) == 0 ]] || skip "the SLURM daemons of this test run as root; this is not root"

work=$(mktemp -d /tmp/lbdem-slurm.XXXXXX)
pids=()
job=""
stop() {
    if [[ -n $job ]]; then scancel "$job" 2>/dev/null || true; fi
    for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
    for pid in "${pids[@]}"; do
        for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
        kill -9 "$pid" 2>/dev/null || true
    done
    rm -rf "$work"
}
trap stop EXIT
show_logs() { tail -n 20 "$work"/*.log 2>/dev/null || true; }

# munge: a fresh key and socket of our own.
mkdir -p "$work/munge"
chmod 700 "$work" "$work/munge"
dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$work/munge/munge.key"
socket=$work/munge/munge.socket
munged --force --socket="$socket" --key-file="$work/munge/munge.key" --pid-file="$work/munge/munged.pid" \
    --log-file="$work/munged.log" --seed-file="$work/munge/munged.seed" || { show_logs; skip "munged did not start"; }
for _ in $(seq 50); do [[ -s $work/munge/munged.pid ]] && break; sleep 0.1; done
pids+=("$(cat "$work/munge/munged.pid")")

# slurm.conf of this node: its hostname, CPUs and memory as slurmd -C finds them.
node=$(slurmd -C 2>/dev/null | head -n 1) && [[ $node == NodeName=* ]] || skip "slurmd -C could not describe this node"
host=$(hostname -s)
port=$((20000 + RANDOM % 20000))
mkdir -p "$work/state" "$work/spool"
cat >"$work/slurm.conf" <<EOF
ClusterName=lbdemtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
MailProg=/bin/true
$node NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$work/slurm.conf
slurmctld -D -c -f "$SLURM_CONF" >/dev/null 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" >/dev/null 2>&1 &
pids+=($!)
for _ in $(seq 60); do
    state=$(sinfo -h -n "$host" -o %T 2>/dev/null || true)
    [[ $state == idle ]] && break
    sleep 0.5
done
[[ $state == idle ]] || { show_logs; skip "SLURM did not start: the node is '${state:-unknown}' after 30 s"; }
echo "SLURM is up: node $host idle (slurm.conf: $node)"

# Submit the 4-task sweep.
rm -rf "$out"
submitted=$("$lbdem" sweep "$sweep" --out "$out" --seeds 2 --slurm --time 00:05:00 --cpus-per-task 1) ||
    fail "lbdem sweep --slurm failed: $submitted"
echo "$submitted"
[[ -f $out/sweep.sbatch ]] || fail "no $out/sweep.sbatch"
grep -q '^#SBATCH --array=0-3$' "$out/sweep.sbatch" || fail "sweep.sbatch is not a 4-task array"
job=$(sed -n 's/^submitted job \([0-9]*\).*/\1/p' <<<"$submitted")
[[ -n $job ]] || fail "lbdem did not say which job it submitted"
for _ in $(seq 200); do
    [[ -z $(squeue -h -j "$job" 2>/dev/null) ]] && break
    sleep 0.5
done
[[ -z $(squeue -h -j "$job" 2>/dev/null) ]] || { squeue; show_logs; fail "job $job still queued or running after 100 s"; }
ran=$(ls "$out"/slurm/task_*.out 2>/dev/null | wc -l)
[[ $ran == 4 ]] || { show_logs; fail "expected 4 task outputs in $out/slurm, found $ran"; }

# Gather the report and check it: each case over its 2 seeds, both finished.
report=$("$lbdem" sweep "$sweep" --out "$out" --seeds 2 --report) || fail "lbdem sweep --report failed: $report"
for name in loose_0deg_dry loose_5deg_dry; do
    for seed in 1 2; do
        grep -q '"finished": true' "$out/${name}_s$seed/summary.json" ||
            fail "${name}_s$seed did not finish: $(tail -n 5 "$out/${name}_s$seed/log.txt" 2>/dev/null)"
    done
    grep -q "^$name,0.79,[0-9.]*,dry,2,2,0," "$out/sweep.csv" || fail "sweep.csv lacks '$name' over 2 seeds: $(cat "$out/sweep.csv")"
done
grep -q '^"loose, dry: runout grows with slope",0 deg to 5 deg,' "$out/findings.csv" ||
    fail "findings.csv lacks the slope finding: $(cat "$out/findings.csv")"
grep -q '## Findings' "$out/sweep.md" || fail "sweep.md has no findings"
echo "ok: 4 SLURM tasks ran; $(wc -l <"$out/sweep.csv") lines in sweep.csv"

# Resubmitting finds every run finished: each task exits at once.
sbatch --wait --parsable "$out/sweep.sbatch" >/dev/null || fail "the resubmitted array failed"
grep -q ': finished$' "$out/slurm/task_0.out" || fail "a resubmitted task did not skip its finished run"
echo "ok: the resubmitted array skipped the finished runs"
