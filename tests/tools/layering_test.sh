#!/usr/bin/env bash
# No include runs against the written layering: the layers listed at the top
# of src/CMakeLists.txt ("#   layer N: folder ..."), where a folder of
# src/vahf/ may include only folders of lower layers. Every folder must be
# listed. Then the check itself is checked on a copy with an include that runs
# upward, which must fail naming the file.
#
# Usage: layering_test.sh REPO_ROOT
set -uo pipefail
root="$1"
source "$(dirname "$0")/check_of_a_check.sh"

# check ROOT: prints each include against the layers; exit 1 if there is one.
check() {
  local dir="$1" bad=0 folder layer file from to
  declare -A level
  while read -r layer folder; do
    level[$folder]=$layer
  done < <(sed -nE 's/^#   layer ([0-9]+): (.*)$/\1 \2/p' "$dir/src/CMakeLists.txt" |
    awk '{ for (i = 2; i <= NF; ++i) print $1, $i }')
  for folder in "$dir"/src/vahf/*/; do
    folder=$(basename "$folder")
    if [ -z "${level[$folder]:-}" ]; then
      echo "src/vahf/$folder/ is in no layer of src/CMakeLists.txt"
      bad=1
    fi
  done
  while IFS=: read -r file to; do
    from="${file#"$dir"/src/vahf/}"
    from="${from%%/*}"
    [ "$from" = "$to" ] && continue
    if [ -z "${level[$to]:-}" ] || [ "${level[$to]}" -ge "${level[$from]:-0}" ]; then
      echo "${file#"$dir"/}: $from (layer ${level[$from]:-?}) includes $to (layer ${level[$to]:-?})"
      bad=1
    fi
  done < <(grep -rHoP --include='*.h' --include='*.cc' --include='*.def' \
    '^\s*#\s*include\s+"vahf/\K[a-z_]+(?=/)' "$dir/src/vahf" | sort -u)
  return "$bad"
}

passes "includes against the layers of src/CMakeLists.txt" check "$root"
mkdir -p "$work/copy/src/vahf/core" "$work/copy/src/vahf/stats"
printf '#   layer 0: core\n#   layer 1: stats\n' >"$work/copy/src/CMakeLists.txt"
printf '#include "vahf/core/error.h"\n' >"$work/copy/src/vahf/stats/a.cc"
passes "the check refuses an include downward" check "$work/copy"
printf '#include "vahf/stats/a.h"\n' >"$work/copy/src/vahf/core/b.cc"
catches "an include upward" "src/vahf/core/b.cc: core (layer 0) includes stats (layer 1)" \
  check "$work/copy"
verdict "every include runs down the layers, and one running up is caught"
