#!/usr/bin/env python3
"""scripts/check-docs against scratch trees: a clean one passes, and each kind of offence is
refused with FILE:LINE and a non-zero exit. Run by ctest as check_docs_test."""
import pathlib
import subprocess
import sys
import tempfile

CHECKER = pathlib.Path(__file__).resolve().parent.parent / "scripts" / "check-docs"

CLEAN = {
    "README.md": "# A project\n\nSee [the docs](docs/page.md) and ![a figure](docs/images/figure.png).\n",
    "docs/page.md": (
        "# A page\n\n[Back](../README.md), [a section](#a-page), [the web](https://example.org).\n\n"
        "| a table row may be long | " + "x" * 300 + " |\n\n```\n" + "y" * 300 + "\n```\n\n"
        "A colour #444444 is not an issue number.\n"
    ),
    "docs/images/figure.png": "",
    "docs/design/note.md": "# A decision\n\n**Choice.** The queue: 12 % faster on `scripts/benchmarks`.\n",
    "CHANGELOG.md": "# Changelog\n\n## 0.1 (2026-11-27)\n\n- Fixed in session 41 (issue 13): history is allowed here.\n",
    "lib/src/code.cpp": "// Resolves the worst contact first.\nint main() { return 0; }\n",
    "scripts/page": "echo 'a{border:1px solid #999}' \"$#\"\n",
    "tests/fuzz_corpus/scene_loader/input": "# 2026-11-27 #13: a fuzzer's input, not prose\n",
}

OFFENCES = {
    "a broken link": ("docs/page.md", "See [missing](missing.md).\n", "docs/page.md:1", "does not resolve"),
    "a broken image": ("README.md", "![gone](docs/images/gone.png)\n", "README.md:1", "does not resolve"),
    "a date": ("docs/page.md", "Measured on 2026-11-27.\n", "docs/page.md:1", "a date"),
    "a session number": ("lib/src/code.cpp", "// Added in session 41.\n", "lib/src/code.cpp:1", "a session number"),
    "an issue number": ("apps/tool.cpp", "// See issue 13.\n", "apps/tool.cpp:1", "an issue number"),
    "a hash issue number": ("docs/page.md", "Fixed in #13.\n", "docs/page.md:1", "an issue number"),
    "a date in a design note": (
        "docs/design/note.md", "Measured on 2026-11-27.\n", "docs/design/note.md:1", "a date"
    ),
    "an issue number in a design note": (
        "docs/design/note.md", "Dropped in issue 13.\n", "docs/design/note.md:1", "an issue number"
    ),
    "a date in a test's comment": (
        "tests/stack_test.cpp", "// Holds since 2026-11-27.\n", "tests/stack_test.cpp:1", "a date"
    ),
    "an issue number in a benchmark": (
        "benchmarks/bench.cpp", "/// Issue 15's target.\n", "benchmarks/bench.cpp:1", "an issue number"
    ),
    "a run-log phrase": ("docs/page.md", "This run was faster tonight.\n", "docs/page.md:1", "a run-log phrase"),
    "a long line": ("docs/page.md", "word " * 50 + "\n", "docs/page.md:1", "characters"),
}


def make_tree(root, files):
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")


def run(root):
    return subprocess.run([sys.executable, str(CHECKER), str(root)], capture_output=True, text=True)


def main():
    failures = []
    with tempfile.TemporaryDirectory() as scratch:
        clean = pathlib.Path(scratch) / "clean"
        make_tree(clean, CLEAN)
        result = run(clean)
        if result.returncode != 0:
            failures.append(f"the clean tree is refused:\n{result.stdout}")
        for what, (name, text, where, message) in OFFENCES.items():
            tree = pathlib.Path(scratch) / what.replace(" ", "_")
            make_tree(tree, {**CLEAN, name: text})
            result = run(tree)
            expected = [line for line in result.stdout.splitlines() if line.startswith(where + ":") and message in line]
            if result.returncode == 0 or not expected:
                failures.append(f"{what} in {name} is not refused as {where}: ...{message}...:\n{result.stdout}")
    for failure in failures:
        print("FAIL:", failure)
    print(f"check_docs_test: {len(OFFENCES) + 1 - len(failures)} of {len(OFFENCES) + 1} cases pass")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
