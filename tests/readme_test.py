#!/usr/bin/env python3
"""Every fenced code block of README.md compiles or runs, so that what a user copies works.

  cpp      verbatim part (indentation aside) of a source file every build compiles (demos/*.cpp, tests/*.cpp; the
           tests run them: demos/parc_simple_setup.cpp, tests/ReadmeExamplesTest.cpp)
  cmake    verbatim part of tests/consumer/CMakeLists.txt (configured, built and run by install.consumer)
  ini      a benchmark configuration: ompl_parc_benchmark --check accepts it
  json     a scenario file the demo reads and plans on (solved or timed out, never refused), or, with
           "```json solution of ARGS", a solution file ompl_parc_validate ARGS accepts
  console  "$ COMMAND" lines run; every output line shown must be printed
  sh       every command runs from a scratch folder laid out like the repository (build/bin is the tested
           build's), except: cmake/ctest builds and scripts/{setup,build,demo,test}.sh -- the set-up and test
           commands CI itself runs from this README -- which must exist, and Google Benchmark targets, listed
           with --benchmark_list_tests (a full run takes minutes), and mpirun commands where ompl_parc_mpi was not
           built (sanitizer trees)
  python   run from a scratch folder by the Python the module was built for, the module on its path
  text     output samples and layouts; a synopsis line starting with a tool names only options its --help has
Usage: readme_test.py SOURCE_DIR BIN_DIR BENCHMARKS_BUILT [PYTHON PYTHONPATH]
  BENCHMARKS_BUILT: 1 or 0 (without them, their commands are skipped); without PYTHON (a build without the module),
  python blocks are skipped
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

src, bindir = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
benchmarks_built = sys.argv[3] == "1"
python, pythonpath = (sys.argv[4], os.path.abspath(sys.argv[5])) if len(sys.argv) > 5 else (None, None)
readme = open(os.path.join(src, "README.md")).read()
# The README's mpirun commands: run where ompl_parc_mpi was built (not in sanitizer trees), on any core count, and as
# root where the tests run as root (CI), which Open MPI refuses otherwise.
mpi_built = os.path.exists(os.path.join(bindir, "ompl_parc_mpi"))
os.environ["OMPI_MCA_rmaps_base_oversubscribe"] = "1"
if os.geteuid() == 0:
    os.environ.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
failures = []
counts = {}


def fail(block, why):
    failures.append(f"block {block['n']} ({block['lang']}, line {block['line']}): {why}")


def sources(*folders):
    """The C++ sources directly in the folders: the tools and examples of demos/, the test files of tests/, all built
    by every build (the Python binding, fuzz target and benchmarks, in subfolders, are not)."""
    texts = []
    for folder in folders:
        path = os.path.join(src, folder)
        texts += [open(os.path.join(path, f)).read() for f in sorted(os.listdir(path)) if f.endswith(".cpp")]
    return texts


def contains(text, lines):
    """Whether \e lines (stripped) are a contiguous run of \e text's lines (stripped)."""
    stripped = [line.strip() for line in text.split("\n")]
    return any(stripped[k:k + len(lines)] == lines for k in range(len(stripped) - len(lines) + 1))


def run(args, cwd, timeout=120):
    return subprocess.run(args, cwd=cwd, capture_output=True, text=True, timeout=timeout)


def tool(name):
    return os.path.join(bindir, name)


scratches = []


def scratch():
    """A folder laid out like the repository: build/bin -> the tested binaries, scripts/ and demos/ linked, an
    empty docs/, so that commands writing build/... or docs/... write there. Removed at the end."""
    root = tempfile.mkdtemp()
    scratches.append(root)
    os.makedirs(os.path.join(root, "build"))
    os.symlink(os.path.abspath(bindir), os.path.join(root, "build", "bin"))
    for folder in ("scripts", "demos"):
        os.symlink(os.path.join(src, folder), os.path.join(root, folder))
    os.makedirs(os.path.join(root, "docs"))
    return root


blocks = []
for m in re.finditer(r"^```([^\n]*)\n(.*?)^```", readme, re.M | re.S):
    info = m.group(1).split()
    blocks.append({"n": len(blocks) + 1, "lang": info[0] if info else "", "info": info[1:],
                   "body": m.group(2), "line": readme.count("\n", 0, m.start()) + 1})

compiled = sources("demos", "tests")
consumer = open(os.path.join(src, "tests", "consumer", "CMakeLists.txt")).read()
SKIPPED_SCRIPTS = {"scripts/setup.sh", "scripts/build.sh", "scripts/demo.sh", "scripts/test.sh"}

for b in blocks:
    lang, body = b["lang"], b["body"]
    counts[lang] = counts.get(lang, 0) + 1
    if lang == "cpp":
        # Lines compared without their indentation: the README shows a function body's lines flush left.
        lines = [line.strip() for line in body.strip("\n").split("\n")]
        if not any(contains(text, lines) for text in compiled):
            fail(b, "not a verbatim part of any compiled source in demos/ or tests/ (indentation aside)")
    elif lang == "cmake":
        if body not in consumer:
            fail(b, "not a verbatim part of tests/consumer/CMakeLists.txt")
    elif lang == "ini":
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "readme.cfg")
            open(path, "w").write(body)
            r = run([tool("ompl_parc_benchmark"), "--check", path], tmp)
            if r.returncode != 0:
                fail(b, "ompl_parc_benchmark --check refused it: " + r.stderr.strip())
    elif lang == "json":
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "readme.json")
            open(path, "w").write(body)
            if b["info"][:2] == ["solution", "of"]:
                r = run([tool("ompl_parc_validate")] + b["info"][2:] + [path], tmp)
                if r.returncode != 0:
                    fail(b, "ompl_parc_validate refused it: " + (r.stdout + r.stderr).strip())
            else:
                r = run([tool("ompl_parc_demo"), "--scenario-file", path, "--time-limit", "5", "--smooth", "0"], tmp)
                if r.returncode not in (0, 1):
                    fail(b, "ompl_parc_demo refused it: " + r.stderr.strip())
    elif lang == "console":
        root = scratch()
        lines = body.rstrip("\n").split("\n")
        for k, line in enumerate(lines):
            if not line.startswith("$ "):
                continue
            shown = []
            for out in lines[k + 1:]:
                if out.startswith("$ "):
                    break
                shown.append(out)
            r = run(["bash", "-c", line[2:]], root)
            printed = (r.stdout + r.stderr).split("\n")
            for out in shown:
                if out not in printed:
                    fail(b, f"'{line[2:]}' did not print '{out}'; it printed: {(r.stdout + r.stderr).strip()}")
    elif lang == "sh":
        root = scratch()
        for command in body.replace("\\\n", " ").split("\n"):
            command = command.split(" #")[0].strip()
            if not command or command.startswith("#"):
                continue
            program = shlex.split(command)[0]
            if program in ("cmake", "ctest") or program in SKIPPED_SCRIPTS:
                if program in SKIPPED_SCRIPTS and not os.access(os.path.join(src, program), os.X_OK):
                    fail(b, f"{program} is not an executable script")
                continue
            if program == "mpirun" and not mpi_built:
                continue
            if program.startswith("build/bin/ompl_parc_bench_"):
                if not benchmarks_built:
                    continue
                command = program + " --benchmark_list_tests=true"
            r = run(["bash", "-c", command], root, timeout=300)
            if r.returncode != 0:
                fail(b, f"'{command}' exited {r.returncode}: {(r.stdout + r.stderr).strip()[-500:]}")
    elif lang == "python":
        if python is None:
            continue
        root = scratch()
        r = subprocess.run([python, "-c", body], cwd=root, capture_output=True, text=True, timeout=300,
                           env={**os.environ, "PYTHONPATH": pythonpath})
        if r.returncode != 0:
            fail(b, f"exited {r.returncode}: {(r.stdout + r.stderr).strip()[-800:]}")
    elif lang == "text":
        for line in body.split("\n"):
            words = line.split()
            if words and os.path.exists(tool(words[0])):
                helptext = run([tool(words[0]), "--help"], src).stdout
                for option in re.findall(r"(--[a-z][a-z-]*)", line):
                    if option not in helptext:
                        fail(b, f"{words[0]} has no option {option}")
    else:
        fail(b, f"unknown block language '{lang}': tag it cpp, cmake, ini, json, console, sh, python or text")

for root in scratches:
    shutil.rmtree(root, ignore_errors=True)
print("README code blocks checked: " + ", ".join(f"{n} {lang}" for lang, n in sorted(counts.items())))
for f in failures:
    print("FAIL: " + f)
sys.exit(1 if failures else 0)
