"""Table of scripts/bench.sh runs: phases from PETSc's -log_view ascii_csv (max over ranks),
counts from the spcontact summary block. Usage: bench_table.py DIR RUN... (writes DIR/bench.csv)."""
import csv
import os
import sys

PHASES = [  # column, stages (their summary rows) or events, summed over every stage
    ("setup", "stages", ["SP mesh", "SP setup"]),
    ("bulk_res", "events", ["SPBulkResidual"]),
    ("bulk_jac", "events", ["SPBulkJacobian"]),
    ("c_search", "events", ["SPContactSearch"]),
    ("c_assem", "events", ["SPContactAssem", "SPShiftUpdate"]),  # minus the search nested in them
    ("pc_setup", "events", ["PCSetUp"]),
    ("lin_solve", "events", ["KSPSolve"]),
    ("output", "stages", ["SP output"]),
]


def summary(path):
    vals, on = {}, False
    with open(path, errors="replace") as f:
        for line in f:
            if line.startswith("=== spcontact summary"):
                on = True
            elif line.startswith("=== end summary"):
                on = False
            elif on and " " in line.strip():
                k, v = line.split(None, 1)
                vals[k] = v.strip()
    return vals


def log_times(path):
    """{(stage, event): {rank: time}}; stage totals are the 'summary' event rows"""
    t = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            key = (row["Stage Name"], row["Event Name"])
            t.setdefault(key, {})[int(row["Rank"])] = float(row["Time"])
    return t


def phase(t, kind, names):
    per_rank = {}
    for (stage, event), ranks in t.items():
        hit = (kind == "stages" and event == "summary" and stage in names) or (kind == "events" and event in names)
        if hit:
            for r, v in ranks.items():
                per_rank[r] = per_rank.get(r, 0.0) + v
    return max(per_rank.values()) if per_rank else 0.0


def main():
    out, names = sys.argv[1], sys.argv[2:]
    rows, floors = [], {}
    for name in names:
        s = summary(os.path.join(out, name + ".txt"))
        logf = os.path.join(out, name + ".log.csv")
        if not s or not os.path.exists(logf):
            print(f"{name}: no summary or log (failed run?)", file=sys.stderr)
            continue
        t = log_times(logf)
        n, p, method = name.split("_", 2)
        r = {"case": name, "dofs": int(s.get("dofs", 0)), "ranks": int(s.get("ranks", 0)),
             "method": method, "newton": int(s.get("newton_iterations", 0)),
             "linear": int(s.get("linear_iterations", 0)), "converged": s.get("converged", "?"),
             "max_pen": s.get("contact_max_penetration", "-")}
        for col, kind, what in PHASES:
            r[col] = phase(t, kind, what)
        # PETSc event times are inclusive: gap evaluations (SPContactSearch) run inside the
        # residual (SPContactAssem) and the shift hook (SPShiftUpdate); count them once
        r["c_assem"] = max(0.0, r["c_assem"] - r["c_search"])
        r["total"] = float(s.get("wall_time", "nan"))
        r["other"] = r["total"] - sum(r[c] for c, _, _ in PHASES)
        r["solve"] = phase(t, "stages", ["SP solve"])
        r["mem_MiB"] = float(s.get("memory_peak_rank_mib", "nan"))
        if method == "floor":
            floors[(n, p)] = r["solve"]
        rows.append(r)
    for r in rows:
        n, p, _ = r["case"].split("_", 2)
        f = floors.get((n, p))
        r["it/floor"] = (r["solve"] / max(r["newton"], 1)) / f if f else float("nan")
    cols = ["dofs", "ranks", "method", "newton", "linear"] + [c for c, _, _ in PHASES] + ["other", "total", "it/floor", "mem_MiB", "max_pen", "converged"]
    with open(os.path.join(out, "bench.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(cols)
        for r in rows:
            w.writerow([f"{r[c]:.4g}" if isinstance(r[c], float) else r[c] for c in cols])
    width = {c: max(len(c), 8) for c in cols}
    width["method"], width["max_pen"] = 8, 10
    fmt = lambda c, v: (f"{v:.3g}" if c == "max_pen" else f"{v:.2f}" if isinstance(v, float) else str(v)) if not (c == "max_pen" and v == "-") else "-"
    print("  ".join(c.rjust(width[c]) for c in cols))
    for r in rows:
        cells = []
        for c in cols:
            v = r[c]
            if c == "max_pen" and v != "-":
                v = float(v)
            cells.append(fmt(c, v).rjust(width[c]))
        print("  ".join(cells))
    print(f"(seconds; phases are PETSc log stages/events, max over ranks; CSV: {os.path.join(out, 'bench.csv')})")


if __name__ == "__main__":
    main()
