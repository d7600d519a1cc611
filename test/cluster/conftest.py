"""The SLURM cluster of one host the cluster tests share (scripts/slurm_cluster.sh: Debian's
munge, slurmctld and slurmd on ports of their own, state in a temporary folder, stopped at the
end), and the environment their commands run in."""
import json
import os
import signal
import socket
import subprocess
import tempfile
from pathlib import Path

import pytest

SOURCE = Path(__file__).resolve().parents[2]
SCRIPTS = SOURCE / "scripts"
DEVEL = Path(os.environ.get("ARI_DEVEL_DIR", SOURCE / "_build" / "devel"))
HANG_GUARD_S = 900  # a job that has not ended by then is stuck, not slow
# The clusters these tests started, by the pid of the pytest that started them: a run killed
# outright cannot stop its daemons, so the next run does.
REGISTRY = Path(tempfile.gettempdir()) / "ari_social_sim_test_clusters"
DAEMONS = ("munged", "slurmctld", "slurmd")


def free_port_pair():
    """A port whose next one is free too (slurmctld's and slurmd's)."""
    for _ in range(50):
        with socket.socket() as probe:
            probe.bind(("", 0))
            port = probe.getsockname()[1]
        if port < 65000:
            with socket.socket() as second:
                try:
                    second.bind(("", port + 1))
                    return port
                except OSError:
                    continue
    raise RuntimeError("no two consecutive free ports")


def sourced_environment(setup):
    """The environment a user has after `source setup.bash`: what the tools, catkin_find and the
    learning package need, and what sbatch passes on to the jobs."""
    dump = subprocess.run(["bash", "-c", "source %s && env -0" % setup], check=True,
                          capture_output=True).stdout.decode()
    return dict(entry.split("=", 1) for entry in dump.split("\0") if "=" in entry)


def alive(pid, names=None):
    try:
        name = Path("/proc/%d/comm" % pid).read_text().strip()
    except OSError:
        return False
    return names is None or name in names


def stop_orphaned_clusters():
    """Stops the daemons of clusters whose pytest died without stopping them (killed outright)."""
    for entry in REGISTRY.glob("*.json") if REGISTRY.is_dir() else []:
        if alive(int(entry.stem)):
            continue
        for pid in json.loads(entry.read_text())["daemons"]:
            if alive(pid, DAEMONS):
                os.kill(pid, signal.SIGKILL)
        entry.unlink()


def register(folder):
    """Notes this run's cluster daemons, so that a later run can stop them should this one die."""
    pid_files = [folder / "munge" / "munged.pid", folder / "slurmctld.pid", folder / "slurmd.pid"]
    daemons = [int(p.read_text()) for p in pid_files if p.exists()]
    REGISTRY.mkdir(exist_ok=True)
    entry = REGISTRY / ("%d.json" % os.getpid())
    entry.write_text(json.dumps({"folder": str(folder), "daemons": daemons}))
    return entry


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    if os.geteuid() != 0:
        pytest.skip("the single-host cluster runs as root (slurmd starts the jobs)")
    stop_orphaned_clusters()
    folder = tmp_path_factory.mktemp("slurm")
    port = free_port_pair()
    subprocess.run(["bash", str(SCRIPTS / "slurm_cluster.sh"), "start", str(folder), str(port)],
                   check=True, capture_output=True, text=True)
    entry = register(folder)
    env = sourced_environment(DEVEL / "setup.bash")
    env["SLURM_CONF"] = str(folder / "slurm.conf")
    yield env
    subprocess.run(["bash", str(SCRIPTS / "slurm_cluster.sh"), "stop", str(folder)])
    entry.unlink()
