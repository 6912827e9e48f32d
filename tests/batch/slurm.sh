#!/bin/bash
# A real single-node Slurm cluster from Debian's packages, configured in a
# temporary folder: `sbatch --array=0-3 --wait` runs `phongrast batch` over a
# 40-job manifest, and every image must equal a single process's byte for
# byte. Needs root (the daemons run as root here); skipped, saying why,
# otherwise. The daemons this script starts are stopped by their process ids,
# also when it fails; a munged that was already running is used and left alone.
# Usage: slurm.sh PHONGRAST
set -u
PHONGRAST=$1
. "$(dirname "$0")/scheduler_common.sh"

[ "$(id -u)" = 0 ] || skip "not root: this test starts munged, slurmctld and slurmd"
for program in /usr/sbin/munged /usr/sbin/slurmctld /usr/sbin/slurmd /usr/bin/sbatch /usr/bin/sinfo /usr/bin/munge \
               /usr/bin/unmunge; do
  [ -x "$program" ] || skip "$program is missing (apt-get install munge slurmctld slurmd slurm-client)"
done
[ -r /etc/munge/munge.key ] || skip "/etc/munge/munge.key is missing (the munge package creates it)"

started=()  # pids of the daemons started here
stop_daemons() {
  local pid
  for pid in "${started[@]}"; do
    kill "$pid" 2> /dev/null
  done
  for pid in "${started[@]}"; do  # munged is not our child: wait by polling
    for _ in $(seq 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
  done
  rm -rf "$work"
}
make_work_folder
trap stop_daemons EXIT

show_logs() {
  echo "--- slurmctld.log"; tail -n 30 "$work/slurmctld.log" 2> /dev/null
  echo "--- slurmd.log"; tail -n 30 "$work/slurmd.log" 2> /dev/null
  for f in "$work"/task-*.out; do [ -e "$f" ] && { echo "--- $f"; cat "$f"; }; done
}

# munge: use the running daemon if there is one, else start ours.
if munge -n 2> /dev/null | unmunge > /dev/null 2>&1; then
  echo "munged is already running: using it"
else
  mkdir -p /run/munge && chown munge:munge /run/munge
  runuser -u munge -- /usr/sbin/munged || { echo "FAILED: munged did not start"; exit 1; }
  pid=$(cat /run/munge/munged.pid)
  started+=("$pid")
  munge -n | unmunge > /dev/null || { echo "FAILED: munge does not work"; exit 1; }
fi

# Two free TCP ports, so that no other Slurm on the machine is disturbed.
port_is_free() { ! ss -Htln "( sport = :$1 )" | grep -q .; }
ports=()
for candidate in $(seq $((20000 + RANDOM % 20000)) 1 $((40100 + RANDOM % 100))); do
  port_is_free "$candidate" && ports+=("$candidate")
  [ "${#ports[@]}" = 2 ] && break
done

host=$(hostname)
mkdir -p "$work/state" "$work/spool"
cat > "$work/slurm.conf" <<EOF_CONF
ClusterName=phongrasttest
SlurmctldHost=$host
SlurmctldPort=${ports[0]}
SlurmdPort=${ports[1]}
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF_CONF
export SLURM_CONF=$work/slurm.conf

# In the foreground (-D) as children of this script, so $! is the daemon itself.
/usr/sbin/slurmctld -D -i -f "$SLURM_CONF" > /dev/null 2>&1 &
started+=("$!")
/usr/sbin/slurmd -D -f "$SLURM_CONF" > /dev/null 2>&1 &
started+=("$!")

for _ in $(seq 60); do
  [ "$(sinfo -h -o %t 2> /dev/null)" = idle ] && break
  sleep 0.5
done
[ "$(sinfo -h -o %t 2> /dev/null)" = idle ] || { echo "FAILED: the Slurm node is not idle after 30 s"; show_logs; exit 1; }

write_manifest || exit 1
cat > "$work/task.sh" <<EOF_TASK
#!/bin/bash
exec "$PHONGRAST" batch "$work/jobs.jsonl" -o "$work/out" --quiet
EOF_TASK
chmod +x "$work/task.sh"
if ! timeout 240 sbatch --wait --array=0-3 --output="$work/task-%a.out" "$work/task.sh"; then
  echo "FAILED: sbatch --wait --array=0-3 did not succeed"
  show_logs
  exit 1
fi
check_sharded_run "$work/out" 4 || { show_logs; exit 1; }
echo "ok: a 4-task Slurm job array = one process"
