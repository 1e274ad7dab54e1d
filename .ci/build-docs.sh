#!/usr/bin/env bash
# Build the documentation and the gallery with warnings as errors, then check the built
# site in headless Chromium (tests/test_docs.py): the pages over HTTP, and every page from
# file:// with the network cut (formulas typeset by the vendored MathJax, animation players
# with their icons, no request outside the site).  The build itself needs no network
# (intersphinx reads docs/_intersphinx/).  Run from anywhere; .ci/run calls it inside the
# virtual environment where the package is installed with its test extra.
set -euo pipefail
cd "$(dirname "$0")/.."

python -m pip install --quiet -e ".[docs]"

export MPLBACKEND=agg
start=$(date +%s)
rm -rf docs/_build/html docs/auto_examples
python -m sphinx -W --keep-going -b html docs docs/_build/html
seconds=$(( $(date +%s) - start ))
echo "documentation built in ${seconds} s (limit 600 s)"
if [ "$seconds" -gt 600 ]; then
  echo "error: the documentation build took ${seconds} s, more than 10 minutes" >&2
  exit 1
fi

# the browser check of the built pages (skips, saying why, without Chromium)
python -m pytest -q tests/test_docs.py -p no:cacheprovider
