"""Runs `plume bench NAME --quick` and checks every output line is a JSON
object with the agreed fields (bench, case, ours_s, peer, peer_s, ratio,
peak_rss_mb) and consistent values (ratio = peer_s / ours_s, times > 0)."""
import json
import math
import subprocess
import sys

exe, name = sys.argv[1], sys.argv[2]
out = subprocess.run([exe, "bench", name, "--quick"], check=True, capture_output=True, text=True).stdout
lines = [l for l in out.splitlines() if l.strip()]
assert lines, "no benchmark output"
for line in lines:
    row = json.loads(line)
    for key in ("bench", "case", "ours_s", "peer", "peer_s", "ratio", "peak_rss_mb"):
        assert key in row, f"missing {key!r} in {line}"
    assert row["bench"] == name, line
    assert row["ours_s"] > 0 and row["peer_s"] > 0, line
    assert math.isclose(row["ratio"], row["peer_s"] / row["ours_s"], rel_tol=1e-6), line
    print(line)
print(f"{len(lines)} benchmark lines OK")
