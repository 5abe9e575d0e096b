#!/usr/bin/env python3
"""gcsim rerun RUN.json repeats a run from its provenance block and compares the simulated figures:
a radiosity run (relative --config, run from the source tree, rerun from elsewhere) and a ray-tracing
run are reported identical with their outputs written elsewhere and the originals untouched; a run
JSON whose machine hash was edited is refused (exit 3) unless --force; one whose simulated time was
edited is reported as differing (exit 1), naming the figure. The trace files and images a run wrote
are compared byte for byte with the rerun's: all identical; one edited is named as differing (exit 1);
one deleted is named as not compared.

  rerun_test.py GCSIM SOURCE_DIR WORKDIR
"""
import hashlib
import json
import pathlib
import shutil
import subprocess
import sys

IDENTICAL, DIFFER, REFUSED = 0, 1, 3


def run(gcsim, args, cwd):
    proc = subprocess.run([gcsim, *args], capture_output=True, text=True, cwd=cwd)
    return proc.returncode, proc.stdout + proc.stderr


def check(cond, what, output=""):
    if not cond:
        sys.exit(f"FAIL: {what}\n{output}")
    print(f"ok: {what}")


def digest(paths):
    return {p: hashlib.sha256(pathlib.Path(p).read_bytes()).hexdigest() for p in paths}


def recorded_and_rerun(gcsim, source, work, name, args):
    code, out = run(gcsim, [*args, "--json", str(work / f"{name}.json")], source)
    check(code == 0, f"{name}: the run succeeds", out)
    doc = json.loads((work / f"{name}.json").read_text())
    prov = doc["provenance"]
    check(prov["command_line"][1:] == [*args, "--json", str(work / f"{name}.json")], f"{name}: argv recorded exactly")
    check(prov["machine"]["hash"].startswith("fnv1a64:") and prov["version"] and prov["commit"], f"{name}: machine hash, version, commit")
    originals = digest(prov["outputs"])
    check(len(originals) >= 3, f"{name}: outputs recorded ({', '.join(originals)})")
    redo = work / f"{name}-rerun"
    code, out = run(gcsim, ["rerun", str(work / f"{name}.json"), "--out-dir", str(redo)], work)
    check(code == IDENTICAL and "identical: all" in out, f"{name}: rerun reports identical", out)
    files = [p for p in prov["outputs"] if p.endswith((".png", ".csv", ".paje")) or "trace" in p]
    check(all(p in out for p in files) and "file(s) the run wrote are the rerun's byte for byte" in out,
          f"{name}: its trace files and image compared identical ({len(files)})", out)
    check(digest(prov["outputs"]) == originals, f"{name}: the recorded outputs are untouched")
    check((redo / f"{name}.json").exists() and len(list(redo.iterdir())) >= 3, f"{name}: the rerun wrote into --out-dir")
    return doc


def main():
    gcsim, source, work = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    rad = recorded_and_rerun(gcsim, source, work, "rad", [
        "run", "radiosity", "--scene", "cornell", "--nodes", "4", "--hemicube", "32", "--energy", "0.9",
        "--config", "configs/gc-powerplus.toml", "--trace", str(work / "rad-trace.json"), "--image", str(work / "rad.png")])
    check(rad["provenance"]["scene"] == {"builtin": "cornell"}, "rad: the built-in scene named")
    rt = recorded_and_rerun(gcsim, source, work, "rt", [
        "run", "raytrace", "--scene", "scenes/meshes/tetrahedron.obj", "--size", "48", "--nodes", "4",
        "--image", str(work / "rt.png"), "--trace", str(work / "rt-trace.json"), "--trace-level", "messages"])
    check(rt["provenance"]["scene"]["hash"].startswith("fnv1a64:"), "rt: the scene file hashed")

    tampered = json.loads((work / "rad.json").read_text())
    tampered["provenance"]["machine"]["hash"] = "fnv1a64:0000000000000000"
    (work / "tampered.json").write_text(json.dumps(tampered))
    code, out = run(gcsim, ["rerun", str(work / "tampered.json")], work)
    check(code == REFUSED and "machine file 'configs/gc-powerplus.toml'" in out and "--force" in out,
          "a machine hash edited: refused, naming the file", out)
    code, out = run(gcsim, ["rerun", str(work / "tampered.json"), "--force", "--out-dir", str(work / "forced")], work)
    check(code == IDENTICAL and "warning" in out, "--force reruns it anyway (with a warning)", out)

    edited = json.loads((work / "rt.json").read_text())
    edited["simulated"]["total_s"] += 1e-3
    (work / "edited.json").write_text(json.dumps(edited))
    code, out = run(gcsim, ["rerun", str(work / "edited.json"), "--out-dir", str(work / "edited")], work)
    check(code == DIFFER and "/simulated/total_s" in out, "an edited simulated time: differs, the figure listed", out)

    csv, paje = work / "rad-trace.csv", work / "rad-trace.paje"
    csv.write_text(csv.read_text() + "0,0,0\n")
    paje.unlink()
    code, out = run(gcsim, ["rerun", str(work / "rad.json"), "--out-dir", str(work / "files")], work)
    check(code == DIFFER and "identical: all" in out and f"differ:   1 file(s)" in out and str(csv) in out,
          "an edited trace CSV: the figures are identical, the file named as differing", out)
    check(f"not compared: {paje} (no longer there)" in out, "a deleted trace file: named, not compared", out)

    code, out = run(gcsim, ["rerun", str(work / "rad.json"), "--out-dir", str(work)], work)
    check(code == REFUSED and "never overwrites" in out, "a rerun into the recorded run's own files is refused", out)


if __name__ == "__main__":
    main()
