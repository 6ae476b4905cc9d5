#!/usr/bin/python3
"""Compare two builds' `plume bench` jobs, interleaved, on a shared machine.

Runs single benchmark jobs (plume-bench NAME --job JOB, each in its own
process as `plume bench` does) with an OLD and a NEW plume-bench, job by job
and alternately (old then new in odd rounds, new then old in even ones), so
that both see the same load; writes one JSON line per run and prints a
Markdown table: median time per job and metric for each side, new/old, the
per-round ratios, and the errors of both (volume: RMS/max against the
reference job, computed once by the NEW binary so the same reference judges
both; sheets (the office-sheet jobs): RMS/max of the 32x32 samples as fractions of
the reference's range, and whether old and new samples are identical; splat: the job's own).

Usage (run under a display; the references need the driver's process id, so
run the jobs through this script, not by hand):
  xvfb-run -a -s "-screen 0 1024x768x24" /usr/bin/python3 scripts/bench-compare.py \
      --old OLD/build/bin/plume-bench --new build/bin/plume-bench --rounds 3 --out results.jsonl
  /usr/bin/python3 scripts/bench-compare.py --report results.jsonl
--new-lib DIR puts DIR first on LD_LIBRARY_PATH for the new binary (for a copy
of a build's bin/ and lib/ taken before the build dir changes; RUNPATH yields).
--old and --new are split like a shell command line, so a build from before
plume-bench existed (the jobs ran inside the plume executable) is given as
--old "OLD/build/bin/plume bench". --skip BENCH:JOB leaves out a job (repeatable),
e.g. one the old build does not have; --also BENCH:JOB adds one (repeatable).
--only runs the --also jobs alone (no default list, no default references);
--reference BENCH:JOB adds a reference job (run once by the new binary, e.g.
volume:reference:dense:256 or sheets:reference:512 for full-size jobs);
--new-env NAME=VALUE sets an environment variable for the new binary only.
"""
import argparse, glob, json, math, os, resource, shlex, statistics, subprocess, time

# (bench, job, --quick): 128^3 volume at 512^2, glyphs 64^3, 10k splats -> 128^3,
# and the sheet jobs that finish in seconds (the quick 128^2 office sheet, the
# 1 278-triangle fire at 256^2); the full-size sheets take minutes per frame here.
JOBS = [
    ("volume", "ours:dense:128:1", False),
    ("volume", "ours:smoke+shaded:128:1", False),
    ("volume", "ours:smoke+iso:128:1", False),
    ("glyphs", "ours:64", False),
    ("glyphs", "adaptive:64", False),
    ("splat", "cpu:scalar:10000:128:1.5", False),
    ("splat", "gpu:scalar:10000:128:1.5", False),
    ("splat", "gpu:vector:10000:128:1.5", False),
    ("splat", "handover:on:10000:128:1.5", False),
    ("sheets", "ours:128:A:8", True),
    ("sheets", "ours:128:V:0.5", True),
    ("sheets", "tris:0:ours", False),
]
REFERENCES = [("volume", "reference:dense:128", False), ("volume", "reference:smoke+shaded:128", False),
              ("sheets", "reference:128", True)]
TIMES = {"volume": ["render_s"], "glyphs": ["first_s", "rerender_s"], "splat": ["seconds", "frame_s"],
         "sheets": ["render_s"]}


def run(binary, env, bench, job, quick):
    args = shlex.split(binary) + [bench, "--job", job] + (["--quick"] if quick else [])
    t0 = time.time()
    p = subprocess.Popen(args, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    stdout, stderr = p.communicate()
    # the job's CPU time (its own threads, llvmpipe's included): far less
    # sensitive to other users' load than wall-clock times
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = usage.ru_utime + usage.ru_stime - run.cpu
    run.cpu = usage.ru_utime + usage.ru_stime
    lines = stdout.strip().splitlines()
    try:
        result = json.loads(lines[-1])
    except (IndexError, ValueError):
        result = {"failed": (stdout + stderr)[-400:]}
    return {"rc": p.returncode, "wall": time.time() - t0, "cpu_s": cpu, "load": os.getloadavg(), "result": result}


run.cpu = 0.0


def measure(a):
    env_old = dict(os.environ)
    env_old.pop("LD_LIBRARY_PATH", None)
    env_new = dict(env_old)
    if a.new_lib:
        env_new["LD_LIBRARY_PATH"] = a.new_lib
    for assignment in a.new_env:
        name, _, value = assignment.partition("=")
        env_new[name] = value
    with open(a.out, "a") as out:
        def record(**kw):
            out.write(json.dumps(kw) + "\n")
            out.flush()
        if a.references_from:
            # an earlier run's references (same --out file): the volume jobs find them by our pid
            for name in glob.glob("/tmp/plume-bench-volume-%d-*" % a.references_from):
                os.symlink(name, name.replace("-%d-" % a.references_from, "-%d-" % os.getpid(), 1))
        else:
            extra = [tuple(j.split(":", 1)) + (False,) for j in a.reference]
            for bench, job, quick in ([] if a.only else REFERENCES) + extra:
                record(kind="reference", bench=bench, job=job, **run(a.new, env_new, bench, job, quick))
        for rnd in range(a.first_round, a.first_round + a.rounds):
            if rnd > a.first_round and a.stop_at and time.time() > a.stop_at:
                break
            order = [("old", a.old, env_old), ("new", a.new, env_new)]
            if rnd % 2 == 0:
                order.reverse()
            for bench, job, quick in ([] if a.only else JOBS) + [tuple(j.split(":", 1)) + (False,) for j in a.also]:
                if "%s:%s" % (bench, job) in a.skip:
                    continue
                for who, binary, env in order:
                    record(kind="run", round=rnd, who=who, bench=bench, job=job, **run(binary, env, bench, job, quick))


def report(path):
    rows = [json.loads(l) for l in open(path)]
    refs = {(r["bench"], r["job"]): r["result"] for r in rows if r.get("kind") == "reference"}
    runs = [r for r in rows if r.get("kind") == "run" and r["rc"] == 0]

    def error(bench, job, res):
        if bench == "volume" and "rms_error" in res:
            return (res["rms_error"], res["max_error"])
        if bench == "splat" and "error_rms" in res:
            return (res["error_rms"], res["error_max"])
        # an office-sheet job ours:SIZE:... against reference:SIZE
        size = job.split(":")[1] if job.startswith("ours:") else ""
        ref, got = refs.get(("sheets", "reference:" + size), {}).get("samples"), res.get("samples")
        if bench != "sheets" or not size or not ref or not got:
            return None
        span = max(max(ref) - min(ref), 1e-12)
        e = [abs(g - r) for g, r in zip(got, ref)]
        return (math.sqrt(sum(x * x for x in e) / len(e)) / span, max(e) / span)

    loads = [r["load"][0] for r in runs]
    print("%d runs, %d rounds; 1-minute load average min / median / max: %.1f / %.1f / %.1f" % (
        len(runs), max(r["round"] for r in runs), min(loads), statistics.median(loads), max(loads)))
    print("| bench | job | metric | old median s | new median s | new/old | new/old per round | error old (RMS / max) | error new | samples identical |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    seen = []
    for r in runs:
        if (r["bench"], r["job"]) not in seen:
            seen.append((r["bench"], r["job"]))
    for bench, job in seen:
        rs = [r for r in runs if r["bench"] == bench and r["job"] == job]
        for metric in TIMES[bench] + ["cpu_s"]:
            value = lambda r: r.get(metric) if metric == "cpu_s" else r["result"].get(metric)
            side = {w: {r["round"]: value(r) for r in rs if r["who"] == w and value(r) is not None}
                    for w in ("old", "new")}
            if not side["old"] or not side["new"]:
                continue
            mo, mn = statistics.median(side["old"].values()), statistics.median(side["new"].values())
            per = " ".join("%.2f" % (side["new"][k] / side["old"][k]) for k in sorted(side["old"])
                           if k in side["new"] and side["old"][k] > 0)
            errs = {w: sorted({error(bench, job, r["result"]) for r in rs if r["who"] == w} - {None}) for w in ("old", "new")}
            fmt = lambda es: "; ".join("%.3g / %.3g" % e for e in es) or "–"
            same = ""
            if bench == "sheets":
                samples = {w: {json.dumps(r["result"].get("samples")) for r in rs if r["who"] == w} for w in ("old", "new")}
                same = ("yes" if samples["old"] == samples["new"] and len(samples["old"]) == 1 else "no") \
                    if "null" not in samples["old"] | samples["new"] else "–"
            print("| %s | `%s` | %s | %.4g | %.4g | %.2f | %s | %s | %s | %s |" % (
                bench, job, metric, mo, mn, mn / mo if mo else float("nan"), per, fmt(errs["old"]), fmt(errs["new"]), same))
    # jobs that time as many frames as fit in a budget (sheets: up to 3 or 15 s):
    # their cpu_s compare the same work only where the frame counts agree
    for bench, job in seen:
        frames = {w: [r["result"].get("frames") for r in sorted(runs, key=lambda r: r["round"])
                      if r["bench"] == bench and r["job"] == job and r["who"] == w] for w in ("old", "new")}
        if any(f is not None for f in frames["old"] + frames["new"]):
            print("frames %s `%s`: old %s, new %s" % (bench, job, frames["old"], frames["new"]))


if __name__ == "__main__":
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--old")
    p.add_argument("--new")
    p.add_argument("--new-lib")
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--first-round", type=int, default=1, help="number of the first round (odd: old runs first)")
    p.add_argument("--references-from", type=int, metavar="PID",
                   help="reuse the references an earlier run (process PID, same --out) computed")
    p.add_argument("--stop-at", type=float, help="start no further round after this time (seconds since the epoch)")
    p.add_argument("--skip", action="append", default=[], metavar="BENCH:JOB",
                   help="leave out this job (repeatable), e.g. one the old build does not have")
    p.add_argument("--also", action="append", default=[], metavar="BENCH:JOB",
                   help="run this job too (repeatable; without --quick), after the list's")
    p.add_argument("--only", action="store_true", help="run only the --also jobs and --reference references")
    p.add_argument("--reference", action="append", default=[], metavar="BENCH:JOB",
                   help="compute this reference too (repeatable; new binary, without --quick)")
    p.add_argument("--new-env", action="append", default=[], metavar="NAME=VALUE",
                   help="set this environment variable for the new binary only (repeatable)")
    p.add_argument("--out", default="bench-compare.jsonl")
    p.add_argument("--report", metavar="JSONL")
    a = p.parse_args()
    if a.report:
        report(a.report)
    else:
        if not a.old or not a.new:
            p.error("--old and --new are required to measure")
        measure(a)
