#!/usr/bin/env bash
# Runs the QGIS provider tests (pytest under Debian's /usr/bin/python3, which
# sees python3-qgis; pyenv's python3 on PATH does not). Called by CTest with
# ROOFSWEEP_EXE=<the roofsweep program just built>.
#
# Exit codes: 0 passed; 1 failed; 77 skipped (QGIS missing and
# ROOFSWEEP_REQUIRE_SHARED is not 1, i.e. not in CI).
set -u
HERE=$(cd "$(dirname "$0")" && pwd)
# Overridable to check the skip/fail paths without uninstalling QGIS.
PY=${ROOFSWEEP_QGIS_PYTHON:-/usr/bin/python3}
QGIS_PROCESS=${ROOFSWEEP_QGIS_PROCESS:-/usr/bin/qgis_process.bin}

missing=()
[[ -x $PY ]] || missing+=("$PY")
[[ -x $QGIS_PROCESS ]] || missing+=("$QGIS_PROCESS (package qgis)")
if [[ -x $PY ]]; then
  $PY -c 'import qgis.core' 2>/dev/null || missing+=("python3-qgis")
  $PY -c 'import pytest' 2>/dev/null || missing+=("python3-pytest")
  $PY -c 'from osgeo import ogr' 2>/dev/null || missing+=("python3-gdal")
  [[ -d /usr/share/qgis/python/plugins/processing ]] || missing+=("QGIS Processing plugin (package qgis)")
fi
if ((${#missing[@]})); then
  if [[ "${ROOFSWEEP_REQUIRE_SHARED:-0}" == 1 ]]; then
    echo "FAIL: QGIS test environment missing (ROOFSWEEP_REQUIRE_SHARED=1): ${missing[*]}" >&2
    echo "      install it with: scripts/install-deps.sh --qgis" >&2
    exit 1
  fi
  echo "SKIP: QGIS test environment missing: ${missing[*]} (scripts/install-deps.sh --qgis)"
  exit 77
fi

if [[ -z "${ROOFSWEEP_EXE:-}" || ! -x "${ROOFSWEEP_EXE}" ]]; then
  echo "FAIL: ROOFSWEEP_EXE must name the roofsweep program (got '${ROOFSWEEP_EXE:-}')" >&2
  exit 1
fi

WORK=$(mktemp -d "${TMPDIR:-/tmp}/roofsweep_qgis.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
mkdir -m 700 "$WORK/runtime"
export QT_QPA_PLATFORM=offscreen
export XDG_RUNTIME_DIR="$WORK/runtime"
export PYTHONPATH="/usr/share/qgis/python/plugins:$HERE${PYTHONPATH:+:$PYTHONPATH}"
export ROOFSWEEP_EXE
export ROOFSWEEP_QGIS_PROCESS="$QGIS_PROCESS"
export ROOFSWEEP_SHARED_DIR="${ROOFSWEEP_SHARED_DIR:-${ROOFSWEEP_SHARED_DIR_DEFAULT:-}}"
# Keep the user's own QGIS profile out of it; start_app() makes a temporary one.
unset QGIS_CUSTOM_CONFIG_PATH QGIS_PLUGINPATH

export PYTHONDONTWRITEBYTECODE=1
cd "$HERE"
$PY -m pytest -p no:cacheprovider -q -rsx --basetemp="$WORK/pytest" "$HERE/tests" "$@"
rc=$?
if [[ $rc -eq 5 ]]; then
  echo "FAIL: pytest collected no tests" >&2
  exit 1
fi
exit $rc
