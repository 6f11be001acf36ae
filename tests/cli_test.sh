#!/usr/bin/env bash
# cli_test.sh EXPECTED_RC PATTERN COMMAND...: runs COMMAND, fails unless it
# exits with EXPECTED_RC and its stdout+stderr match the extended regex PATTERN.
# A crash (signal) never counts as the expected code.
set -u
expected=$1 pattern=$2
shift 2
out=$("$@" 2>&1)
rc=$?
if [ "$rc" -ne "$expected" ]; then
  echo "exit code $rc, expected $expected: $*"
  echo "$out" | head -20
  exit 1
fi
if ! grep -Eq -- "$pattern" <<<"$out"; then
  echo "output does not match /$pattern/: $*"
  echo "$out" | head -20
  exit 1
fi
echo "ok: $* -> $rc"
