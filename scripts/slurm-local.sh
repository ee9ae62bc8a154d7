#!/usr/bin/env bash
# A single-node Slurm on this machine (Debian slurm-wlm and munge), then a tiled plot run on it
# through scripts/slurm-tiles.sbatch (docs/scale.md):
#   scripts/slurm-local.sh DIR [RECONSTRUCT-OPTIONS...]
# Needs root (it writes /etc/slurm/slurm.conf and /etc/munge/munge.key when missing and starts
# munged, slurmctld and slurmd). An existing slurm.conf is kept unless it is this script's. Waits
# for the merge job and prints the jobs' accounting (sacct when available, else their logs).
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: $0 DIR [RECONSTRUCT-OPTIONS...]" >&2; exit 2; }
# Slurm is not needed by `make test`, so it is installed here, when this script first runs.
for p in slurm-wlm munge; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends slurm-wlm munge
    break
  fi
done
here=$(cd "$(dirname "$0")" && pwd)
host=$(hostname -s)
cpus=$(nproc)
mem=$(awk '/MemTotal/ {print int($2 / 1024 * 0.8)}' /proc/meminfo)
conf=/etc/slurm/slurm.conf
marker="# written by ramus scripts/slurm-local.sh"
if [ ! -f "$conf" ] || grep -q "$marker" "$conf"; then
  mkdir -p /etc/slurm /var/spool/slurmctld /var/spool/slurmd /var/log/slurm
  cat > "$conf" <<CONF
$marker
ClusterName=ramus-local
SlurmctldHost=$host
AuthType=auth/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ReturnToService=2
SlurmctldPidFile=/run/slurmctld.pid
SlurmdPidFile=/run/slurmd.pid
StateSaveLocation=/var/spool/slurmctld
SlurmdSpoolDir=/var/spool/slurmd
SlurmctldLogFile=/var/log/slurm/slurmctld.log
SlurmdLogFile=/var/log/slurm/slurmd.log
JobAcctGatherType=jobacct_gather/linux
NodeName=$host CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
fi
if [ ! -f /etc/munge/munge.key ]; then
  mkdir -p /etc/munge
  dd if=/dev/urandom bs=1 count=1024 of=/etc/munge/munge.key status=none
  chown munge:munge /etc/munge/munge.key 2>/dev/null || true
  chmod 400 /etc/munge/munge.key
fi
mkdir -p /run/munge && chown munge:munge /run/munge 2>/dev/null || true
pgrep -x munged >/dev/null || su -s /bin/sh munge -c munged 2>/dev/null || munged --force
pgrep -x slurmctld >/dev/null || slurmctld
pgrep -x slurmd >/dev/null || slurmd
# Wait for the node to come up.
for _ in $(seq 1 30); do
  sinfo -h -o %T 2>/dev/null | grep -Eq 'idle|mixed|alloc' && break
  sleep 1
done
sinfo
start=$(date +%s)
submitted=$(bash "$here/slurm-tiles.sbatch" "$@")
echo "$submitted"
merge=$(echo "$submitted" | sed -n 's/.*merge job \([0-9]*\).*/\1/p')
while squeue -h -j "$merge" 2>/dev/null | grep -q .; do sleep 2; done
echo "wall time from submission to merged forest: $(( $(date +%s) - start )) s"
dir=$(cd "$1" && pwd)
tail -n 1 "$dir"/slurm-merge-*.out
[ -f "$dir/forest.json" ] || { echo "$0: the merge job wrote no forest" >&2; exit 1; }
