#!/usr/bin/env python3
"""Writes tests/unity_groups.cmake: the test files that the unity build
(BEZCAM_UNITY, the ci and asan presets) compiles together, per suite.

Files compiled together share one scope: two files of a group must not
define the same name at file scope (helpers, constants, types, macros).
This script reads each file's column-0 definitions (clang-format puts them
there), puts files whose names do not meet in groups of at most 6, then
compiles each group (-fsyntax-only, with the flags of the build's
compile_commands.json) and leaves a file that does not fit its group to
compile alone. A file in no group compiles alone: a new test file needs no
entry; run this script again to group it.

Usage: tests/unity_groups.py BUILD_DIR   (a configured build of the ci preset)
"""
import glob
import json
import os
import re
import shlex
import subprocess
import sys

MAX_GROUP = 6
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFINITION = [
    re.compile(r"^(?:static |inline |constexpr |const |\[\[nodiscard\]\] )*[\w:<>,\*& ]+?[ \*&](\w+)\s*\("),
    re.compile(r"^(?:static |inline )*(?:constexpr|const) [^=;(]*?\b(\w+)(?:\[\w*\])?\s*(?:=|\{)"),
    re.compile(r"^(?:struct|class|union|enum(?: class)?) (\w+)"),
    re.compile(r"^using (\w+) ="),
    re.compile(r"^#define (\w+)"),
    re.compile(r"^template <[^>]*> *(?:[\w:<>,\*& ]+?[ \*&])?(\w+)\s*\("),
    re.compile(r"^[\w:<>]+ (\w+)(?:\[\w*\])?\s*(?:=|\{|;)"),
]
NOT_NAMES = {"TEST", "TEST_F", "TEST_P", "main", "if", "for", "while", "return", "operator", "PrintTo"}


def names(path):
    found = set()
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith((" ", "//", "}", "TEST", "INSTANTIATE", "namespace", "using namespace", "#include",
                                "#if", "#endif", "#else")):
                continue
            for p in DEFINITION:
                m = p.match(line)
                if m and m.group(1) not in NOT_NAMES:
                    found.add(m.group(1))
    return found


def group(files):
    defined = {f: names(f) for f in files}
    groups = []
    for f in sorted(files, key=lambda f: (-len(defined[f]), f)):
        for g in groups:
            if len(g) < MAX_GROUP and not any(defined[f] & defined[h] for h in g):
                g.append(f)
                break
        else:
            groups.append([f])
    return [sorted(g) for g in groups if len(g) > 1]


def suite_command(suite, commands):
    """The compile command of one of the suite's sources (a test file or, in
    a unity build, a group's batch): every source of a suite has the same
    flags."""
    for c in commands:
        if "/%s_tests.dir/" % suite in c["command"]:
            return c
    sys.exit("no source of %s_tests in compile_commands.json: configure the build first" % suite)


def compiles(files, command):
    args = shlex.split(command["command"])
    i = args.index("-o")
    del args[i:i + 2]
    batch = os.path.join(os.path.dirname(files[0]), "zz_unity_check.cpp")
    with open(batch, "w", encoding="utf-8") as f:
        f.write("".join('#include "%s"\n' % x for x in files))
    try:
        args = [batch if a == command["file"] else a for a in args] + ["-fsyntax-only"]
        return subprocess.run(args, cwd=command["directory"], capture_output=True).returncode == 0
    finally:
        os.remove(batch)


def checked(groups, command):
    out = []
    for g in groups:
        kept = [g[0]]
        for f in g[1:]:
            if compiles(kept + [f], command):
                kept.append(f)
        if len(kept) > 1:
            out.append(kept)
        print("  %s: %d of %d" % (os.path.relpath(g[0], ROOT), len(kept), len(g)), file=sys.stderr)
    return out


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    with open(os.path.join(sys.argv[1], "compile_commands.json"), encoding="utf-8") as f:
        commands = json.load(f)
    lines = ["# Written by tests/unity_groups.py (read it before editing): the test",
             "# files each unity group compiles together. A file in no group compiles alone."]
    # A suite is a folder of tests/ with *_test.cpp files (tests/CMakeLists.txt).
    suites = sorted({os.path.basename(os.path.dirname(f)) for f in glob.glob(os.path.join(ROOT, "tests", "*", "*_test.cpp"))})
    for suite in suites:
        files = sorted(glob.glob(os.path.join(ROOT, "tests", suite, "*.cpp")))
        groups = checked(group(files), suite_command(suite, commands))
        for n, g in enumerate(groups):
            lines.append("bezcam_unity_group(%s %d %s)" % (suite, n, " ".join(os.path.basename(f) for f in g)))
    with open(os.path.join(ROOT, "tests", "unity_groups.cmake"), "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
