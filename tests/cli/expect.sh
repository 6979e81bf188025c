#!/usr/bin/env bash
# expect.sh CODE [--stderr REGEX] [--stdout REGEX] -- COMMAND...
# Runs COMMAND and fails unless it exits with CODE and its output matches.
set -u
code=$1; shift
err_re=""; out_re=""
while [ "$1" != "--" ]; do
  case "$1" in
    --stderr) err_re=$2; shift 2 ;;
    --stdout) out_re=$2; shift 2 ;;
    *) echo "expect.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
shift
out=$(mktemp); err=$(mktemp)
trap 'rm -f "$out" "$err"' EXIT
"$@" >"$out" 2>"$err"
got=$?
status=0
if [ "$got" != "$code" ]; then
  echo "exit status $got, expected $code: $*"; status=1
fi
if [ -n "$err_re" ] && ! grep -Eq -- "$err_re" "$err"; then
  echo "stderr does not match /$err_re/"; status=1
fi
if [ -n "$out_re" ] && ! grep -Eq -- "$out_re" "$out"; then
  echo "stdout does not match /$out_re/"; status=1
fi
if [ $status != 0 ]; then
  echo "--- stdout"; head -c 2000 "$out"; echo "--- stderr"; head -c 2000 "$err"
fi
exit $status
