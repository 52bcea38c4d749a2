#!/usr/bin/env bash
# Executes the worked notebook docs/examples/vahf_tour.ipynb with jupyter
# nbconvert (Debian's jupyter-nbconvert and python3-ipykernel) on the
# module of this build, matplotlib's Agg backend, within a time budget, and
# checks that every plot it writes is there and is a PNG. The notebook is
# stored without outputs; the executed copy goes to OUT.
#
# Usage: notebook_test.sh MODULE_DIR OUT (from the repository's root)
set -euo pipefail
budget=300  # s a cell; the notebook takes about 20 s on 2 cores
rm -rf "$2"
mkdir -p "$2"
module_dir="$(cd "$1" && pwd)"  # absolute: the kernel starts in docs/examples
out="$(cd "$2" && pwd)"
export PYTHONPATH="$module_dir${PYTHONPATH:+:$PYTHONPATH}"
export MPLBACKEND=Agg
export VAHF_NOTEBOOK_OUT="$out"
/usr/bin/python3 -m jupyter nbconvert --to notebook --execute \
  --ExecutePreprocessor.timeout="$budget" --ExecutePreprocessor.kernel_name=python3 \
  --output-dir "$out" --output vahf_tour.ipynb docs/examples/vahf_tour.ipynb
for plot in trace.png cycle_times.png kappa_sweep.png; do
  if [[ "$(head -c 4 "$out/$plot" 2>/dev/null | tail -c 3)" != PNG ]]; then
    echo "notebook_test: $out/$plot was not written" >&2
    exit 1
  fi
done
echo "notebook_test: the notebook ran and wrote its 3 plots into $out"
