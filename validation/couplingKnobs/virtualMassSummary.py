#!/usr/bin/python3
"""Table and metrics of validation/couplingKnobs/virtualMassSeries: RESULTS/virtualMass.md
and RESULTS/metrics.json (virtual_mass_max_change_pct: the largest change of the settling
speed at 0.2 s against the default C_v 0.5) from RESULTS/virtualMass.csv.

    virtualMassSummary.py RESULTS
"""
import csv
import json
import os
import sys

out = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(out, "virtualMass.csv"))))
ref = next(r for r in rows if r["virtualMass"] == "0.5")
lines = ["| virtualMass C_v | u_z(0.2 s) (m/s) | vs the default 0.5 | s/step |", "|---|---|---|---|"]
change = 0.0
for r in rows:
    rel = 100 * (float(r["uz"]) / float(ref["uz"]) - 1)
    change = max(change, abs(rel))
    lines.append(f"| {r['virtualMass']} | {float(r['uz']):.5f} | "
                 f"{'-' if r is ref else f'{rel:+.2f} %'} | {float(r['secondsPerStep']):.3f} |")
with open(os.path.join(out, "virtualMass.md"), "w") as f:
    f.write("\n".join(lines) + "\n")
with open(os.path.join(out, "metrics.json"), "w") as f:
    json.dump({"virtual_mass_max_change_pct": round(change, 4)}, f, indent=1, sort_keys=True)
    f.write("\n")
