#!/usr/bin/env python3
"""The narrow doors between applications (docs/ARCHITECTURE.md, "Layers").

An application is a folder of apps/ whose CMakeLists.txt calls gcsim_add_app. Applications do not
include each other, except a composite, which may include another application's public header
(apps/<app>/<app>.hpp) and nothing else of it; the shared folders (common, pipeline, programs,
cli) include no application at all. Prints every include that breaks the rule and fails if any.

usage: app_doors.py SOURCE_DIR
"""
import re
import sys
from pathlib import Path

COMPOSITES = {"render", "calibration"}  # apps that drive another app's program
SHARED = {"common", "pipeline", "programs", "cli"}
INCLUDE = re.compile(r'^\s*#\s*include\s*"apps/([^/"]+)/([^"]+)"')


def applications(apps_dir):
    return {d.name for d in apps_dir.iterdir()
            if (d / "CMakeLists.txt").is_file() and "gcsim_add_app" in (d / "CMakeLists.txt").read_text()}


def violation(owner, target, header, apps):
    """Why `owner` (a folder of apps/) may not include apps/<target>/<header>, or None."""
    if target == owner or target not in apps:
        return None
    if owner in SHARED:
        return "shared code includes no application"
    if owner not in COMPOSITES:
        return f"'{owner}' is not a composite: it includes no other application"
    if header != f"{target}.hpp":
        return f"a composite includes only apps/{target}/{target}.hpp of '{target}'"
    return None


def main(source_dir):
    apps_dir = Path(source_dir) / "apps"
    apps = applications(apps_dir)
    missing = COMPOSITES - apps
    if missing:
        print(f"app_doors.py: composites {sorted(missing)} are not applications under {apps_dir}")
        return 1
    problems = []
    for path in sorted(apps_dir.rglob("*")):
        if path.suffix not in {".hpp", ".cpp", ".h", ".cc"} or not path.is_file():
            continue
        owner = path.relative_to(apps_dir).parts[0]
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            m = INCLUDE.match(line)
            why = m and violation(owner, m.group(1), m.group(2), apps)
            if why:
                problems.append(f"{path.relative_to(source_dir)}:{number}: {line.strip()}: {why}")
    for p in problems:
        print(p)
    print(f"{len(problems)} include(s) through a wrong door; applications {sorted(apps)}, composites {sorted(COMPOSITES)}")
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
