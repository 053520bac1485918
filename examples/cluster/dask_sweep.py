"""A speed sweep on Dask workers (user guide: "Sweeps beyond one machine"): one `frictrack.run` per speed, mapped
over the workers of a cluster, gathered into the CSV `frictrack sweep` writes for the same speeds.

    python examples/cluster/dask_sweep.py [SCENARIO] [--speeds A:B:STEP] [--workers N] [--out sweep.csv]

Here on a LocalCluster of N worker processes (one thread each: every run uses one core); on a Slurm cluster the same
code runs on dask-jobqueue's SLURMCluster — replace the cluster line with, e.g.,

    from dask_jobqueue import SLURMCluster
    cluster = SLURMCluster(cores=1, memory="2GB", walltime="01:00:00"); cluster.scale(jobs=32)

frictrack schedules nothing across machines itself: Dask does. Needs `pip install ./crates/python "dask[distributed]"`.
"""

import argparse

import frictrack

#: Sweep CSV columns and where a run's summary holds each: an extreme's value, a term of the energy balance.
COLUMNS = {
    "speed": ("speed",),
    "max_downward_deflection": ("max_downward_deflection", "value"),
    "max_upward_deflection": ("max_upward_deflection", "value"),
    "dissipated_energy": ("energy", "dissipated"),
    "global_norm": ("global_norm",),
}


def run_case(case):
    """One run: the scenario with its speed (a top-level function, so that the workers can unpickle it)."""
    run = frictrack.run(case["scenario"], speed=case["speed"])
    row = {}
    for name, path in COLUMNS.items():
        value = run.summary
        for key in path:
            value = value[key]
        row[name] = value
    return row


def speeds_of(text):
    start, stop, step = (float(x) for x in text.split(":"))
    count = int(round((stop - start) / step)) + 1
    return [start + i * step for i in range(count)]


def sweep(scenario, speeds, workers):
    """The rows of the sweep, in the order of `speeds`, computed on a LocalCluster of `workers` processes."""
    from dask.distributed import Client, LocalCluster

    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True) as cluster, Client(cluster) as client:
        futures = client.map(run_case, [{"scenario": scenario, "speed": v} for v in speeds])
        return client.gather(futures)


def csv(rows):
    """The rows as CSV, numbers written as Python's repr (the shortest that reads back to the same float)."""
    lines = [",".join(COLUMNS)]
    lines += [",".join(repr(float(row[name])) for name in COLUMNS) for row in rows]
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scenario", nargs="?", default=None, help="scenario file (default: the reference case)")
    parser.add_argument("--speeds", default="100:300:50", help="A:B:STEP in m/s")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--out", default=None, help="write the CSV here instead of standard output")
    args = parser.parse_args()
    text = csv(sweep(args.scenario, speeds_of(args.speeds), args.workers))
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)
    else:
        print(text, end="")
