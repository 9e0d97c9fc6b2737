"""A one-node Slurm cluster on this machine for taa-farm's test (Debian's slurmctld, slurmd,
munge; run as root). Everything it starts has its own key, socket, ports, state, spool and pid
files under one temporary folder, so it never touches a cluster the machine already runs, and
it stops exactly the processes it started.

Interpreter: Debian's /usr/bin/python3 (standard library only).
"""
import os
import shutil
import signal
import socket
import subprocess
import tempfile
import time

REQUIRED = ("munged", "mungekey", "slurmctld", "slurmd", "sbatch", "scontrol", "squeue", "sinfo")


class SlurmUnavailable(Exception):
    """This machine cannot run the daemons (not root, packages missing, munged will not start)."""


def free_ports(count):
    """Ports nothing listens on now: bound once by the kernel's choice, then released."""
    sockets = [socket.socket() for _ in range(count)]
    try:
        for s in sockets:
            s.bind(("", 0))
        return [s.getsockname()[1] for s in sockets]
    finally:
        for s in sockets:
            s.close()


def wait_for(condition, timeout, what, interval=0.2):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if condition():
            return
        time.sleep(interval)
    raise TimeoutError(f"timed out after {timeout} s waiting for {what}")


class SlurmCluster:
    """with SlurmCluster() as cluster: subprocess.run(["sbatch", ...], env=cluster.env)"""

    def __init__(self):
        self.folder = None
        self.pids = {}
        self.env = None

    def __enter__(self):
        if os.geteuid() != 0:
            raise SlurmUnavailable("the Slurm daemons need root (slurmd runs jobs as their user)")
        missing = [tool for tool in REQUIRED if not shutil.which(tool)]
        if missing:
            raise SlurmUnavailable("not installed: " + ", ".join(missing) +
                                   " (scripts/install-deps.sh installs them)")
        # Short: a unix socket's path holds at most 107 bytes.
        self.folder = tempfile.mkdtemp(prefix="taa-slurm-", dir="/tmp")
        try:
            self._start_munge()
            self._start_slurm()
        except BaseException:
            self.stop()
            raise
        return self

    def __exit__(self, *_exc):
        self.stop()

    def path(self, name):
        return os.path.join(self.folder, name)

    def log_tail(self, name, lines=20):
        try:
            with open(self.path(name), errors="replace") as log:
                return "".join(log.readlines()[-lines:])
        except OSError:
            return "(no log)"

    def _start_munge(self):
        os.chmod(self.folder, 0o755)  # munged checks the socket folder is reachable
        subprocess.run(["mungekey", "--create", "--keyfile", self.path("munge.key")],
                       check=True, capture_output=True)
        os.chmod(self.path("munge.key"), 0o600)
        started = subprocess.run(
            ["munged", "--force", "--socket", self.path("munge.socket"),
             "--key-file", self.path("munge.key"), "--pid-file", self.path("munged.pid"),
             "--log-file", self.path("munged.log"), "--seed-file", self.path("munged.seed")],
            capture_output=True, text=True)
        if started.returncode != 0:
            raise SlurmUnavailable(f"munged does not start here: {started.stderr.strip()}\n"
                                   + self.log_tail("munged.log"))
        wait_for(lambda: os.path.exists(self.path("munged.pid")), 10, "munged's pid file")
        self.pids["munged"] = self._pid("munged.pid")

    def _start_slurm(self):
        host = socket.gethostname().split(".")[0]
        ctld_port, slurmd_port = free_ports(2)
        for folder in ("state", "spool"):
            os.makedirs(self.path(folder))
        config = f"""# taa-farm's test cluster: one node, this host (reached on 127.0.0.1, whether or not its name
# resolves), its own ports and folders.
ClusterName=taatest
SlurmctldHost={host}(127.0.0.1)
SlurmctldPort={ctld_port}
SlurmdPort={slurmd_port}
SlurmUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket={self.path("munge.socket")}
StateSaveLocation={self.path("state")}
SlurmdSpoolDir={self.path("spool")}
SlurmctldPidFile={self.path("slurmctld.pid")}
SlurmdPidFile={self.path("slurmd.pid")}
SlurmctldLogFile={self.path("slurmctld.log")}
SlurmdLogFile={self.path("slurmd.log")}
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
MpiDefault=none
ReturnToService=2
MinJobAge=3600
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
NodeName={host} NodeAddr=127.0.0.1 CPUs={os.cpu_count()} RealMemory=1000 State=UNKNOWN
PartitionName=taa Nodes={host} Default=YES MaxTime=INFINITE State=UP
"""
        with open(self.path("slurm.conf"), "w") as conf:
            conf.write(config)
        self.env = dict(os.environ, SLURM_CONF=self.path("slurm.conf"))
        for daemon, args in (("slurmctld", ["-c"]), ("slurmd", [])):
            started = subprocess.run([daemon, "-f", self.path("slurm.conf"), *args],
                                     capture_output=True, text=True, env=self.env)
            if started.returncode != 0:
                raise RuntimeError(f"{daemon} failed: {started.stderr}\n"
                                   + self.log_tail(f"{daemon}.log"))
            wait_for(lambda d=daemon: os.path.exists(self.path(f"{d}.pid")), 20,
                     f"{daemon}'s pid file\n" + self.log_tail(f"{daemon}.log"))
            self.pids[daemon] = self._pid(f"{daemon}.pid")

        def node_idle():
            state = subprocess.run(["sinfo", "-h", "-o", "%T"], capture_output=True, text=True,
                                   env=self.env).stdout.strip()
            return state == "idle"
        try:
            wait_for(node_idle, 30, "the node to be idle")
        except TimeoutError as error:
            raise RuntimeError(f"{error}\n{self.log_tail('slurmctld.log')}"
                               f"{self.log_tail('slurmd.log')}") from error

    def _pid(self, name):
        """The pid a daemon wrote (waiting until the file holds it)."""
        def read():
            try:
                with open(self.path(name)) as pid_file:
                    words = pid_file.read().split()
            except OSError:
                return None
            return int(words[0]) if words and words[0].isdigit() else None
        wait_for(lambda: read() is not None, 20, f"a pid in {name}")
        return read()

    def _started_here(self):
        """Processes whose command line names this cluster's folder: daemons it started, also one
        that failed before its pid was read."""
        pids = []
        for entry in os.listdir("/proc"):
            try:
                with open(f"/proc/{entry}/cmdline", "rb") as cmdline:
                    if self.folder.encode() in cmdline.read():
                        pids.append(int(entry))
            except (OSError, ValueError):
                continue
        return pids

    def stop(self):
        """Cancels the jobs, stops the daemons this object started (by their pids) and removes
        its folder."""
        if self.folder is None:
            return
        if self.env and os.path.exists(self.path("slurmctld.pid")):
            jobs = subprocess.run(["squeue", "-h", "-o", "%A"], capture_output=True, text=True,
                                  env=self.env).stdout.split()
            if jobs:
                subprocess.run(["scancel", *sorted(set(jobs))], env=self.env,
                               capture_output=True)
                time.sleep(1)
            subprocess.run(["scontrol", "shutdown"], env=self.env, capture_output=True)
        if os.path.exists(self.path("munge.socket")):
            subprocess.run(["munged", "--stop", "--socket", self.path("munge.socket")],
                           capture_output=True)
        daemons = set(self.pids.values()) | set(self._started_here())
        for pid in daemons:
            name = command_name(pid)
            for stop_signal, wait in ((None, 15), (signal.SIGTERM, 5), (signal.SIGKILL, 5)):
                if stop_signal and alive(pid) and command_name(pid) == name:  # not a reused pid
                    os.kill(pid, stop_signal)
                try:
                    wait_for(lambda p=pid: not alive(p), wait, f"{name} ({pid}) to stop")
                    break
                except TimeoutError:
                    continue
        self.pids.clear()
        shutil.rmtree(self.folder, ignore_errors=True)
        self.folder = None


def command_name(pid):
    try:
        with open(f"/proc/{pid}/comm") as comm:
            return comm.read().strip()
    except OSError:
        return ""


def alive(pid):
    """Whether `pid` runs (a zombie does not count)."""
    try:
        with open(f"/proc/{pid}/stat") as stat:
            return stat.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False
