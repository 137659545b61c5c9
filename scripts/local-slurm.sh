#!/usr/bin/env bash
# A single-node Slurm cluster on localhost, for trying `surfacelab study
# --slurm` and for its integration test (tests/slurm.rs).
#
#   bash scripts/local-slurm.sh          # install if missing, start if not running
#   export SLURM_CONF=/tmp/surfacelab-slurm/slurm.conf
#   bash scripts/local-slurm.sh stop     # stop the daemons (the folder stays)
#
# Installs Debian's `slurm-wlm` and `munge` (and, for job accounting so that
# `sacct` works, `slurmdbd` and `mariadb-server-core`) with apt-get when they
# are missing, then starts munged, a private MariaDB (127.0.0.1 only),
# slurmdbd, slurmctld and slurmd, with their configuration, keys, sockets,
# logs and state in one folder (SURFACELAB_SLURM_DIR, default
# /tmp/surfacelab-slurm), not in /etc. Idempotent: a cluster already answering
# on that folder's configuration is left alone. Made for containers: no
# systemd, no cgroups (proctrack/linuxproc, task/none), SlurmUser=root.
# The last line it prints is the `export SLURM_CONF=...` the clients need.
set -euo pipefail

dir="${SURFACELAB_SLURM_DIR:-/tmp/surfacelab-slurm}"
conf="$dir/slurm.conf"
export SLURM_CONF="$conf"

say() { echo "local-slurm: $*" >&2; }
die() { say "error: $*"; exit 1; }

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; elif command -v sudo >/dev/null 2>&1; then sudo "$@"; else
    die "need root (or sudo) for: $*"
  fi
}

pid_alive() { [ -f "$1" ] && kill -0 "$(cat "$1")" 2>/dev/null; }

stop() {
  local f
  for f in slurmd slurmctld slurmdbd mariadbd munged; do
    if pid_alive "$dir/$f.pid"; then
      as_root kill "$(cat "$dir/$f.pid")" || true
    fi
  done
  say "stopped ($dir)"
}

if [ "${1:-start}" = stop ]; then stop; exit 0; fi
[ "${1:-start}" = start ] || die "usage: $0 [start|stop]"

# 1. Packages, from Debian's archive.
need=()
command -v slurmctld >/dev/null 2>&1 && command -v slurmd >/dev/null 2>&1 && command -v sbatch >/dev/null 2>&1 \
  || need+=(slurm-wlm)
command -v munged >/dev/null 2>&1 || need+=(munge)
command -v slurmdbd >/dev/null 2>&1 || need+=(slurmdbd)
command -v mariadbd >/dev/null 2>&1 || need+=(mariadb-server-core)
if ((${#need[@]})); then
  say "installing ${need[*]} (apt-get)"
  as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi

# 2. Already running? Then leave it.
if pid_alive "$dir/munged.pid" && pid_alive "$dir/slurmdbd.pid" && pid_alive "$dir/slurmctld.pid" \
  && pid_alive "$dir/slurmd.pid" \
  && sinfo -h -o '%T' 2>/dev/null | grep -Eq '^(idle|mixed|allocated)'; then
  say "already running ($dir)"
  echo "export SLURM_CONF=$conf"
  exit 0
fi
stop >/dev/null 2>&1 || true
# Give stopped daemons a moment to release their ports and files.
for _ in $(seq 1 20); do
  alive=0
  for f in slurmd slurmctld slurmdbd mariadbd munged; do pid_alive "$dir/$f.pid" && alive=1; done
  [ "$alive" -eq 0 ] && break
  sleep 0.5
done

# 3. Configuration and keys in the folder. The accounting database and the
# controller's saved state are started afresh every time: they hold nothing a
# later start needs (the cluster is registered again below), and a machine
# stopped mid-write leaves InnoDB files that MariaDB refuses to open
# ("Data structure corruption"), which would make every later start fail.
as_root rm -rf "$dir/mysql" "$dir/ctld" "$dir/spool"
as_root mkdir -p "$dir/munge" "$dir/ctld" "$dir/spool" "$dir/mysql"
as_root chmod 700 "$dir/munge"
if [ ! -s "$dir/munge/munge.key" ]; then
  as_root dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none
fi
as_root chmod 600 "$dir/munge/munge.key"
cpus="$(nproc)"
db_port=6820   # MariaDB, 127.0.0.1 only
dbd_port=6819  # slurmdbd
# RealMemory in MiB, a little under MemTotal so slurmd never reports less.
mem_mib="$(awk '/^MemTotal:/ { printf "%d", $2 / 1024 * 0.95 }' /proc/meminfo)"
as_root tee "$conf" >/dev/null <<CONF
# Written by surfacelab's scripts/local-slurm.sh: one node, localhost.
ClusterName=surfacelab
SlurmctldHost=localhost
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
SlurmctldPort=6817
SlurmdPort=6818
StateSaveLocation=$dir/ctld
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/slurmdbd
AccountingStorageHost=localhost
AccountingStoragePort=$dbd_port
# The munge socket for talking to slurmdbd (AuthInfo covers the rest).
AccountingStoragePass=$dir/munge/munge.socket
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
MinJobAge=3600
NodeName=localhost CPUs=$cpus RealMemory=$mem_mib State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
# slurmdbd reads slurmdbd.conf beside slurm.conf and wants it private.
as_root tee "$dir/slurmdbd.conf" >/dev/null <<CONF
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.socket
DbdHost=localhost
DbdPort=$dbd_port
SlurmUser=root
LogFile=$dir/slurmdbd.log
PidFile=$dir/slurmdbd.pid
StorageType=accounting_storage/mysql
StorageHost=127.0.0.1
StoragePort=$db_port
StorageUser=root
StorageLoc=surfacelab_slurm_acct
CONF
as_root chmod 600 "$dir/slurmdbd.conf"

wait_for() { # seconds, what, command...
  local deadline=$((SECONDS + $1)) what="$2"
  shift 2
  until timeout 10 "$@" >/dev/null 2>&1; do
    if ((SECONDS >= deadline)); then
      say "$what did not start in time; last lines of the logs:"
      tail -n 20 "$dir"/*.log >&2 2>/dev/null || true
      exit 1
    fi
    sleep 0.5
  done
}

# 4. Daemons: munged (its own socket), MariaDB (private and bare: no system
# tables, no grant tables; it listens on 127.0.0.1 only and holds nothing
# but this cluster's accounting), slurmdbd, slurmctld (fresh state), slurmd.
as_root munged --force --num-threads=10 --socket="$dir/munge/munge.socket" --key-file="$dir/munge/munge.key" \
  --pid-file="$dir/munged.pid" --log-file="$dir/munged.log" --seed-file="$dir/munge/munged.seed"
as_root setsid mariadbd --no-defaults --user=root --datadir="$dir/mysql" --bind-address=127.0.0.1 \
  --port="$db_port" --socket="$dir/mysql.sock" --pid-file="$dir/mariadbd.pid" --log-error="$dir/mariadbd.log" \
  --skip-grant-tables --skip-log-bin --innodb-buffer-pool-size=32M </dev/null >/dev/null 2>&1 &
wait_for 60 "MariaDB" bash -c "exec 3<>/dev/tcp/127.0.0.1/$db_port"
as_root slurmdbd
wait_for 60 "slurmdbd" sacctmgr -n list cluster
if ! sacctmgr -n -P list cluster format=cluster 2>/dev/null | grep -qx surfacelab; then
  as_root timeout 30 sacctmgr -i add cluster surfacelab >/dev/null
fi
as_root slurmctld -f "$conf"
as_root slurmd -f "$conf" -N localhost

# 5. Wait for the node to come up.
for _ in $(seq 1 60); do
  if sinfo -h -o '%T' 2>/dev/null | grep -Eq '^(idle|mixed|allocated)'; then
    say "running: $cpus CPUs, $mem_mib MiB, partition debug ($dir)"
    echo "export SLURM_CONF=$conf"
    exit 0
  fi
  sleep 1
done
say "the node did not come up within 60 s; last lines of the logs:"
tail -n 20 "$dir"/*.log >&2 2>/dev/null || true
sinfo >&2 || true
exit 1
