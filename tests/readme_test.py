#!/usr/bin/env python3
"""Every fenced code block of README.md and of the guide's pages (docs/*.md) compiles or runs, so that what a user
copies works; and every relative link of those pages leads to a file that exists, and to a heading of it where it
names an anchor (GitHub's anchors: the heading in lower case, punctuation dropped, spaces as '-', '-1', '-2', ... for
repeats).

  cpp      verbatim part (indentation aside) of a source file every build compiles (demos/*.cpp, tools/*.cpp,
           tests/*.cpp; the tests run them: demos/parc_simple_setup.cpp, tests/ReadmeExamplesTest.cpp)
  cmake    verbatim part of tests/consumer/CMakeLists.txt (configured, built and run by install.consumer)
  ini      a benchmark configuration: ompl_parc_benchmark --check accepts it
  json     a scenario file the demo reads and plans on (solved or timed out, never refused), or, with
           "```json solution of ARGS", a solution file ompl_parc_validate ARGS accepts
  console  "$ COMMAND" lines run; every output line shown must be printed
  sh       every command runs from a scratch folder laid out like the repository (build/bin is the tested
           build's), except: cmake/ctest builds and scripts/{setup,build,demo,test}.sh -- the set-up and test
           commands CI itself runs from the README -- which must exist, and Google Benchmark targets, listed
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
# The pages checked: the README, then the guide's pages in name order.
docs = os.path.join(src, "docs")
pages = ["README.md"] + sorted("docs/" + f for f in os.listdir(docs) if f.endswith(".md"))
# The README's mpirun commands: run where ompl_parc_mpi was built (not in sanitizer trees), on any core count, and as
# root where the tests run as root (CI), which Open MPI refuses otherwise.
mpi_built = os.path.exists(os.path.join(bindir, "ompl_parc_mpi"))
os.environ["OMPI_MCA_rmaps_base_oversubscribe"] = "1"
if os.geteuid() == 0:
    os.environ.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
failures = []
counts = {}


def fail(block, why):
    failures.append(f"{block['page']} block {block['n']} ({block['lang']}, line {block['line']}): {why}")


def sources(*folders):
    """The C++ sources directly in the folders that exist: the tools and examples of demos/ and tools/, the test files
    of tests/, all built by every build (the Python binding, fuzz target and benchmarks, in subfolders, are not)."""
    texts = []
    for folder in folders:
        path = os.path.join(src, folder)
        if not os.path.isdir(path):
            continue
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
    """A folder laid out like the repository: build/bin -> the tested binaries, scripts/, demos/, tools/ and python/
    linked (those that exist), an empty docs/, so that commands writing build/... or docs/... write there. Removed at
    the end."""
    root = tempfile.mkdtemp()
    scratches.append(root)
    os.makedirs(os.path.join(root, "build"))
    os.symlink(os.path.abspath(bindir), os.path.join(root, "build", "bin"))
    for folder in ("scripts", "demos", "tools", "python"):
        if os.path.isdir(os.path.join(src, folder)):
            os.symlink(os.path.join(src, folder), os.path.join(root, folder))
    os.makedirs(os.path.join(root, "docs"))
    return root


FENCE = re.compile(r"^```([^\n]*)\n(.*?)^```", re.M | re.S)


def anchors(text):
    """The GitHub anchors of a page's headings (outside code blocks): lower case, punctuation but '-' and '_'
    dropped, spaces as '-'; a repeated anchor gets -1, -2, ..."""
    found, seen = set(), {}
    for line in FENCE.sub("", text).split("\n"):
        m = re.match(r"#{1,6} (.*)", line)
        if not m:
            continue
        a = re.sub(r"[^\w\- ]", "", m.group(1).strip().lower()).replace(" ", "-")
        found.add(a if a not in seen else f"{a}-{seen[a]}")
        seen[a] = seen.get(a, 0) + 1
    return found


def check_links(page, text):
    """Every relative link [..](target) outside code blocks and code spans leads to a file, and to a heading of a
    Markdown page where it names an anchor."""
    prose = re.sub(r"`[^`]*`", "", FENCE.sub(lambda m: "\n" * m.group(0).count("\n"), text))
    for m in re.finditer(r"\]\(([^)\s]+)\)", prose):
        target = m.group(1)
        if re.match(r"[a-z]+:", target):
            continue
        line = prose.count("\n", 0, m.start()) + 1
        path, _, anchor = target.partition("#")
        where = os.path.normpath(os.path.join(src, os.path.dirname(page), path)) if path else os.path.join(src, page)
        if not os.path.exists(where):
            failures.append(f"{page} line {line}: link to {target}: no such file")
        elif anchor and where.endswith(".md") and anchor not in anchors(open(where).read()):
            failures.append(f"{page} line {line}: link to {target}: no such heading")


blocks = []
for page in pages:
    text = open(os.path.join(src, page)).read()
    check_links(page, text)
    for n, m in enumerate(FENCE.finditer(text), 1):
        info = m.group(1).split()
        blocks.append({"page": page, "n": n, "lang": info[0] if info else "", "info": info[1:],
                       "body": m.group(2), "line": text.count("\n", 0, m.start()) + 1})

compiled = sources("demos", "tools", "tests")
consumer = open(os.path.join(src, "tests", "consumer", "CMakeLists.txt")).read()
SKIPPED_SCRIPTS = {"scripts/setup.sh", "scripts/build.sh", "scripts/demo.sh", "scripts/test.sh"}

for b in blocks:
    lang, body = b["lang"], b["body"]
    counts[lang] = counts.get(lang, 0) + 1
    if lang == "cpp":
        # Lines compared without their indentation: the README shows a function body's lines flush left.
        lines = [line.strip() for line in body.strip("\n").split("\n")]
        if not any(contains(text, lines) for text in compiled):
            fail(b, "not a verbatim part of any compiled source in demos/, tools/ or tests/ (indentation aside)")
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
print(f"Code blocks of {len(pages)} pages checked: " + ", ".join(f"{n} {lang}" for lang, n in sorted(counts.items())))
for f in failures:
    print("FAIL: " + f)
sys.exit(1 if failures else 0)
