"""Tables of validation/couplingKnobs/results/runs.csv: per knob, the settling speed at 0.2 s,
its difference to the series' reference run and the time per step relative to the default
(8 cells/D, penaltyRatio 1e-3, 1 sub-step; the cpd runs include the default's mesh).
Also merges into metrics.json beside runs.csv: cpd_<N>_change_pct (the settling speed against
the finest mesh), penalty_ratio_max_change_pct and sub_steps_max_change_pct (the largest change
over those series)."""
import json
import os
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tools"))
from validationTools import read_csv  # noqa: E402

rows = read_csv(sys.argv[1], missing_ok=False)
default = next((r for r in rows if r["knob"] == "cpd" and r["value"] == "8"), None)
series = {
    "cpd": ("cells per diameter", lambda r: -float(r["value"])),
    "penaltyRatio": ("penaltyRatio (eta/dt)", lambda r: float(r["value"])),
    "subSteps": ("sub-steps", lambda r: float(r["value"])),
}
metrics = {}
for knob, (title, order) in series.items():
    rs = [r for r in rows if r["knob"] == knob]
    if default is not None and knob != "cpd":
        rs.append(dict(default, knob=knob, value={"penaltyRatio": "1e-3", "subSteps": "1"}[knob]))
    if not rs:
        continue
    rs.sort(key=order)
    ref = rs[0]  # finest mesh / smallest penaltyRatio / one sub-step
    print(f"\n### {title} (reference: {ref['value']})\n")
    print("| " + title + " | cells | u_z(0.2 s) (m/s) | settling speed vs reference | s/step | time vs default |")
    print("|---|---|---|---|---|---|")
    for r in sorted(rs, key=lambda r: float(r["value"])):
        u, u0 = float(r["uz"]), float(ref["uz"])
        rel = "-" if r is ref else f"{100 * (abs(u) - abs(u0)) / abs(u0):+.2f} %"
        cost = f"{float(r['secondsPerStep']) / float(default['secondsPerStep']):.2f}x" if default else "-"
        print(f"| {r['value']} | {r['cells']} | {u:.5f} | {rel} | {float(r['secondsPerStep']):.3f} | {cost} |")
        change = 100 * (abs(u) - abs(u0)) / abs(u0)
        if knob == "cpd" and r is not ref:
            metrics[f"cpd_{r['value']}_change_pct"] = round(change, 4)
        elif knob != "cpd":
            key = {"penaltyRatio": "penalty_ratio", "subSteps": "sub_steps"}[knob]
            metrics[f"{key}_max_change_pct"] = round(max(metrics.get(f"{key}_max_change_pct", 0.0),
                                                         abs(change)), 4)
path = os.path.join(os.path.dirname(os.path.abspath(sys.argv[1])), "metrics.json")
merged = json.load(open(path)) if os.path.exists(path) else {}
merged.update(metrics)
with open(path, "w") as f:
    json.dump(merged, f, indent=1, sort_keys=True)
    f.write("\n")
