#!/usr/bin/env bash
# Installs the built tree into a temporary prefix and builds a tiny consumer project against it with
# find_package(ompl_parc) + target_link_libraries(app ompl_parc::ompl_parc), then runs it. The consumer names
# only the prefix, yet must find the OMPL the library was built with (OMPL_VERSION, e.g. one outside the system's
# paths), and compile and run against it. Then, from another folder, the installed tools: --version, a shipped
# scenario file and Panda Cage task solved and validated, a shipped benchmark suite checked, the plot script run.
# Usage: install_test.sh BUILD_DIR CONSUMER_SOURCE_DIR OMPL_VERSION
set -eu
build=$1
consumer=$2
ompl_version=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" >/dev/null
cmake -S "$consumer" -B "$tmp/build" -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_BUILD_TYPE=Release >"$tmp/configure.log"
if ! grep -qx -- "-- consumer: OMPL $ompl_version" "$tmp/configure.log"; then
    echo "the consumer did not find OMPL $ompl_version:"
    cat "$tmp/configure.log"
    exit 1
fi
cmake --build "$tmp/build" -j2 >/dev/null
"$tmp/build/consumer"

mkdir "$tmp/elsewhere"
cd "$tmp/elsewhere"
bin=$tmp/prefix/bin
share=$tmp/prefix/share/ompl_parc
"$bin/ompl_parc_demo" --version | grep -qx "ompl_parc [0-9.]* (OMPL $ompl_version)" || { echo "bad --version"; exit 1; }
for tool in ompl_parc_validate ompl_parc_benchmark ompl_parc_generate ompl_parc_generate_panda_cage; do
    "$bin/$tool" --version >/dev/null || { echo "$tool --version failed"; exit 1; }
done
"$bin/ompl_parc_demo" --scenario-file "$share/scenarios/doorway_swap.json" --seed 1 --out swap.json | grep -q '^validated  yes' ||
    { echo "the installed demo did not solve the shipped doorway_swap.json"; exit 1; }
"$bin/ompl_parc_validate" swap.json --scenario-file "$share/scenarios/doorway_swap.json" >/dev/null ||
    { echo "the installed validator rejected the solution"; exit 1; }
"$bin/ompl_parc_demo" --scenario-file "$share/scenarios/panda_cage/panda_cage_2_0.json" --param profile=panda \
    --smooth 0 | grep -q '^validated  yes' || { echo "the installed demo did not solve the shipped Panda Cage task"; exit 1; }
[ -f "$share/robots/panda.urdf" ] || { echo "no panda.urdf in share/"; exit 1; }
"$bin/ompl_parc_benchmark" --check "$share/benchmarks/quick/mobile_cross_8.cfg" >/dev/null ||
    { echo "a shipped benchmark suite does not check"; exit 1; }
# ompl_parc_mpi (when MPI was found), as a single rank without mpirun (MPI's singleton start).
if [ -x "$bin/ompl_parc_mpi" ]; then
    "$bin/ompl_parc_mpi" --scenario-file "$share/scenarios/doorway_swap.json" --param seed=1 | grep -q '^validated  yes' ||
        { echo "the installed ompl_parc_mpi did not solve the shipped doorway_swap.json"; exit 1; }
fi
# The Python module, installed into the interpreter's package folder under the prefix (when it was built).
for module in "$tmp"/prefix/lib/python3*/*-packages/ompl_parc; do
    [ -d "$module" ] || continue
    PYTHONPATH=$(dirname "$module") /usr/bin/python3 -c "
import ompl_parc
result = ompl_parc.solve(ompl_parc.load('$share/scenarios/doorway_swap.json'), 'arc', seed=1)
assert result.solved and ompl_parc.validate(ompl_parc.load('$share/scenarios/doorway_swap.json'), result.plan).valid
print('install: the installed Python module solved doorway_swap.json')" || { echo "the installed Python module failed"; exit 1; }
done
echo "install: tools, scenarios and suites work from $tmp/elsewhere"
