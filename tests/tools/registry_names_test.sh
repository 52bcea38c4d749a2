#!/usr/bin/env bash
# Each registry (steppers, contact models, experiment kinds) is the only list
# of its names: tests/tools/registry_names.py finds code that selects one of
# them by name, or lists them a second time. The check is then checked on a
# copy of the tree with a selection by name and with a list of every kind
# planted, each of which it must refuse naming the file and line.
#
# Usage: registry_names_test.sh REPO_ROOT
set -uo pipefail
root="$1"
source "$(dirname "$0")/check_of_a_check.sh"
check="$(dirname "$0")/registry_names.py"

passes "the tree's registries are the only lists of their names" python3 "$check" "$root"

copy="$work/copy"
mkdir -p "$copy"
(cd "$root" && tar -cf - src tools tests bench docs/parameters.md docs/kinds.md) |
  (cd "$copy" && tar -xf -)
passes "a copy of the tree" python3 "$check" "$copy"

# A selection by name in the scene loader.
loader="$copy/src/vahf/scene/scene_loader.cc"
cp "$loader" "$work/loader.cc"
printf 'bool Planted(const Scene& c) {\n  return c.params.contact.model == "shell";\n}\n' >>"$loader"
line=$(($(wc -l <"$loader") - 1))
catches "a contact model selected by name" \
  "src/vahf/scene/scene_loader.cc:$line: selects the contact model shell by name" \
  python3 "$check" "$copy"
cp "$work/loader.cc" "$loader"

# A test that lists every kind.
kinds=$(sed -nE 's/^\| `([a-z0-9_]+)` \|.*/"\1"/p' "$root/docs/kinds.md" | paste -sd, -)
planted="$copy/tests/kinds/planted_test.cc"
printf '// every kind\nconst std::vector<std::string> kAll = {\n    %s};\n' "$kinds" >"$planted"
catches "a second list of the kinds" "tests/kinds/planted_test.cc:2: a second list of kind names" \
  python3 "$check" "$copy"
rm "$planted"

verdict "each registry is the only list of its names"
