#!/usr/bin/python3
"""Unit test of validation/tools/validationTools.py (run by tests/foam/validationTools/run)."""
import math
import os
import re
import subprocess
import sys
import tempfile
import threading
import unittest
from pathlib import Path
from unittest import mock

TOOLS = Path(__file__).resolve().parents[3] / "validation" / "tools"
sys.path.insert(0, str(TOOLS))
import validationTools as vt  # noqa: E402

CONTROL_DICT = """\
FoamFile
{
    class       dictionary;
    object      controlDict;
}
// endTime is set per run
endTime         0.06;           // the end
deltaT          0.004;
"""


class Substitution(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.path = os.path.join(self.tmp.name, "controlDict")
        with open(self.path, "w") as f:
            f.write(CONTROL_DICT)

    def tearDown(self):
        self.tmp.cleanup()

    def text(self):
        with open(self.path) as f:
            return f.read()

    def test_found_once_is_replaced_in_the_file(self):
        new = vt.substitute(self.path, "deltaT          0.004;", "deltaT          0.002;")
        self.assertIn("deltaT          0.002;", self.text())
        self.assertNotIn("0.004", self.text())
        self.assertEqual(new, self.text())

    def test_path_object_and_text(self):
        vt.substitute(Path(self.path), "0.004", "0.001")
        self.assertIn("deltaT          0.001;", self.text())
        out = vt.substitute("a b a", "b", "c")
        self.assertEqual(out, "a c a")

    def test_not_found_raises_naming_file_and_pattern(self):
        with self.assertRaises(vt.SubstitutionError) as e:
            vt.substitute(self.path, "deltaT          0.005;", "deltaT          0.002;")
        self.assertIn(self.path, str(e.exception))
        self.assertIn("deltaT          0.005;", str(e.exception))
        self.assertEqual(self.text(), CONTROL_DICT)      # the file is left as it was

    def test_found_twice_when_once_expected_raises(self):
        with self.assertRaises(vt.SubstitutionError) as e:
            vt.substitute(self.path, "endTime", "stopTime")
        self.assertIn("found 2 time(s)", str(e.exception))
        self.assertEqual(self.text(), CONTROL_DICT)
        vt.substitute(self.path, "endTime", "stopTime", count=2)
        self.assertEqual(self.text().count("stopTime"), 2)
        vt.substitute(self.path, "stopTime", "endTime", count=None)
        self.assertEqual(self.text(), CONTROL_DICT)

    def test_not_found_in_text_raises(self):
        with self.assertRaises(vt.SubstitutionError) as e:
            vt.substitute("nu 1e-6;\n", "mu", "nu")
        self.assertIn("'mu'", str(e.exception))

    def test_regex(self):
        vt.substitute_re(self.path, r"^(deltaT\s+)\S+;", r"\g<1>0.002;")
        self.assertIn("deltaT          0.002;", self.text())
        with self.assertRaises(vt.SubstitutionError) as e:
            vt.substitute_re(self.path, r"^maxDeltaT .*$", "maxDeltaT 1;")
        self.assertIn(self.path, str(e.exception))
        self.assertIn("^maxDeltaT .*$", str(e.exception))

    def test_set_entry_hits_the_entry_not_the_comment(self):
        vt.set_entry(self.path, "endTime", "0.2")
        text = self.text()
        self.assertIn("endTime         0.2;           // the end", text)
        self.assertIn("// endTime is set per run", text)

    def test_set_entry_of_a_commented_key_only_raises(self):
        with open(self.path, "a") as f:
            f.write("// maxDeltaT 1;\n")
        with self.assertRaises(vt.SubstitutionError) as e:
            vt.set_entry(self.path, "maxDeltaT", "0.1")
        self.assertIn(self.path, str(e.exception))
        self.assertIn("maxDeltaT", str(e.exception))

    def test_command_line(self):
        tool = [sys.executable, str(TOOLS / "validationTools.py")]
        ok = subprocess.run(tool + ["set", self.path, "deltaT", "0.001"],
                            capture_output=True, text=True)
        self.assertEqual(ok.returncode, 0, ok.stderr)
        self.assertIn("deltaT          0.001;", self.text())
        bad = subprocess.run(tool + ["substitute", self.path, "@NU@", "1e-6"],
                             capture_output=True, text=True)
        self.assertNotEqual(bad.returncode, 0)
        self.assertIn(self.path, bad.stderr)
        self.assertIn("@NU@", bad.stderr)


class Provenance(unittest.TestCase):
    def test_fields(self):
        p = vt.provenance()
        self.assertEqual(sorted(p), ["commit", "date", "host"])
        self.assertTrue(p["host"])
        self.assertRegex(p["date"], r"^\d{4}-\d\d-\d\d \d\d:\d\d$")
        self.assertRegex(p["commit"], r"^([0-9a-f]{4,}(\+src)?|unknown)$")

    def test_outside_a_checkout(self):
        # the temporary folder may lie inside a checkout (build/tests): git stops above it
        with tempfile.TemporaryDirectory() as d, mock.patch.dict(
                os.environ, GIT_CEILING_DIRECTORIES=os.path.dirname(os.path.realpath(d))):
            self.assertEqual(vt.commit(d), "unknown")


class Tables(unittest.TestCase):
    def test_csv_round_trip(self):
        rows = [dict(name="a", value=1.5, note="x, y"), dict(name="b", value=-2, note="")]
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "results", "runs.csv")
            vt.write_csv(path, rows, ["name", "value", "note"])
            back = vt.read_csv(path)
            self.assertEqual(back, [{k: str(v) for k, v in r.items()} for r in rows])
            with self.assertRaises(ValueError):
                vt.write_csv(path, [dict(rows[0], extra=1)], ["name", "value", "note"])
            vt.write_csv(path, [dict(rows[0], extra=1)], ["name", "value", "note"],
                         ignore_extra=True)
            self.assertEqual(list(vt.read_csv(path)[0]), ["name", "value", "note"])
            missing = os.path.join(d, "none.csv")
            self.assertEqual(vt.read_csv(missing), [])
            with self.assertRaises(FileNotFoundError):
                vt.read_csv(missing, missing_ok=False)


    def test_failed_write_keeps_the_file(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "runs.csv")
            vt.write_csv(path, [dict(name="a", value=1)])
            with self.assertRaises(ValueError):
                vt.write_csv(path, [dict(name="b", value=2, extra=3)], ["name", "value"])
            self.assertEqual(vt.read_csv(path), [dict(name="a", value="1")])
            self.assertEqual(os.listdir(d), ["runs.csv"])

    def test_merge_row_from_processes_side_by_side(self):
        # four processes each replace and add rows of one CSV file at once: every row stays,
        # whole, and a replaced row appears once
        import multiprocessing
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "results", "runs.csv")
            vt.write_csv(path, [dict(name="seed", value=0)], ["name", "value"])
            ctx = multiprocessing.get_context("fork")
            workers = [ctx.Process(target=merge_rows, args=(path, w)) for w in range(4)]
            for p in workers:
                p.start()
            for p in workers:
                p.join(60)
                self.assertEqual(p.exitcode, 0)
            rows = vt.read_csv(path, missing_ok=False)
            names = sorted(r["name"] for r in rows)
            expected = sorted(["seed"] + [f"w{w}-{i}" for w in range(4) for i in range(25)])
            self.assertEqual(names, expected)
            self.assertTrue(all(r["value"] == "final" for r in rows if r["name"] != "seed"))


def merge_rows(path, worker):
    """25 rows added by one process and then each replaced (merge_row)."""
    for i in range(25):
        vt.merge_row(path, dict(name=f"w{worker}-{i}", value="first"), "name", ["name", "value"])
    for i in range(25):
        vt.merge_row(path, dict(name=f"w{worker}-{i}", value="final"), "name", ["name", "value"])


class CommittedTables(unittest.TestCase):
    def test_every_row_as_wide_as_its_header(self):
        # the validations' CSV files in the repository (a row split by a write that another
        # run read half done would be narrower or wider); lines starting with # are comments
        import csv
        root = TOOLS.parents[1]
        listed = subprocess.run(["git", "-C", str(root), "ls-files", "validation/*.csv"],
                                capture_output=True, text=True)
        self.assertEqual(listed.returncode, 0, listed.stderr)
        files = sorted(root / f for f in listed.stdout.split())
        self.assertGreater(len(files), 20)
        for f in files:
            with open(f, newline="") as fh:
                rows = [r for r in csv.reader(line for line in fh if not line.startswith("#"))]
            with self.subTest(file=str(f.relative_to(root))):
                self.assertTrue(rows)
                bad = [i for i, r in enumerate(rows[1:], 2) if len(r) != len(rows[0])]
                self.assertEqual(bad, [], f"{f}: rows of another width than the header")


class Logs(unittest.TestCase):
    def test_cpu_seconds_and_cells(self):
        with tempfile.TemporaryDirectory() as d:
            with open(os.path.join(d, "log.solver"), "w") as f:
                f.write("Time = 1\nExecutionTime = 0.5 s  ClockTime = 1 s\n"
                        "Time = 2\nExecutionTime = 1.25 s  ClockTime = 2 s\nEnd\n")
            with open(os.path.join(d, "log.blockMesh"), "w") as f:
                f.write("Mesh Information\n  nPoints: 35\n  nCells: 24\n")
            self.assertEqual(vt.cpu_seconds(d), 1.25)
            self.assertEqual(vt.execution_times(os.path.join(d, "log.solver")), [0.5, 1.25])
            self.assertEqual(vt.mesh_cells(d), 24)
            self.assertTrue(math.isnan(vt.cpu_seconds(os.path.join(d, "none"))))


class RunLogged(unittest.TestCase):
    def test_status_log_and_no_hang(self):
        # a stand-in solver: a few "Time = " lines, then exit status 3
        with tempfile.TemporaryDirectory() as d:
            os.makedirs(os.path.join(d, "system"))
            with open(os.path.join(d, "system", "controlDict"), "w") as f:
                f.write(CONTROL_DICT)
            script = ("for t in 0.02 0.04 0.06; do echo \"Time = $t\"; "
                      "echo \"ExecutionTime = 0.1 s  ClockTime = 1 s\"; sleep 0.2; done; exit 3")
            # run_logged returns only after its progress watcher has ended; a
            # watcher that outlived the run would keep it from returning (the
            # join bound only keeps a broken watcher from hanging the tests)
            result = {}
            worker = threading.Thread(
                target=lambda: result.update(rc=vt.run_logged(["bash", "-c", script], d,
                                                              "log.fakeFoam")))
            worker.start()
            worker.join(120)
            self.assertFalse(worker.is_alive(), "run_logged did not return after the run ended")
            rc = result["rc"]
            self.assertEqual(rc, 3)
            with open(os.path.join(d, "log.fakeFoam")) as f:
                self.assertEqual(len(re.findall(r"^Time = ", f.read(), re.MULTILINE)), 3)


class CaseFiles(unittest.TestCase):
    def test_write_dict(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "constant", "transportProperties")
            vt.write_dict(path, "dictionary", "constant", "transportProperties",
                          "nu              1;\n", "spheroidFoam validation: a test")
            with open(path) as f:
                text = f.read()
            self.assertIn("  spheroidFoam validation: a test\n", text)
            self.assertRegex(text, r"(?s)FoamFile\n\{\n.*class       dictionary;\n"
                                   r"    location    \"constant\";\n"
                                   r"    object      transportProperties;\n\}")
            self.assertIn("\nnu              1;\n", text)
            self.assertTrue(re.search(r"// \*+ //\n$", text))


if __name__ == "__main__":
    unittest.main(verbosity=2)
