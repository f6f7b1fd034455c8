#!/usr/bin/env bash
# The documents against the tool: docs/scene-reference.md's table of every key
# is what `sandpic scene --reference` prints (so no key goes undocumented), and
# every lattice command the README shows runs as written, from a folder that
# has the examples and build/sandpic where the README says they are.
# usage: test_docs.sh SANDPIC SOURCE_DIR
set -euo pipefail
bin=$(realpath "$1")
src=$(realpath "$2")
fail() { echo "FAIL: $*" >&2; exit 1; }

# 1. The key table, between its markers.
page="$src/docs/scene-reference.md"
diff <(sed -n '/<!-- keys:begin -->/,/<!-- keys:end -->/p' "$page" | sed '1d;$d') \
     <("$bin" scene --reference) \
  || fail "docs/scene-reference.md's key table is stale: regenerate it with 'sandpic scene --reference'"
for key in $("$bin" scene --keys | cut -f1); do
  grep -q "| \`$key\` |" "$page" || fail "scene key '$key' is missing from docs/scene-reference.md"
done

# 2. The README's commands: every line of its sh blocks that runs build/sandpic,
# but the studio (a server), DEM runs (minutes; the cli test covers them) and the
# lines with a placeholder in capitals (SCENE, OUT.png).
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/build"
ln -s "$bin" "$work/build/sandpic"
ln -s "$src/examples" "$work/examples"
commands=$(awk '/^```sh/{on=1; next} /^```/{on=0} on' "$src/README.md" \
  | grep '^build/sandpic ' | grep -v -e ' studio' -e '--mode dem' -e '[A-Z][A-Z]*\.\(png\|json\|csv\)' -e ' \[' \
  | sed 's/[[:space:]]\{2,\}#.*$//')
count=$(grep -c . <<<"$commands")
[ "$count" -ge 8 ] || fail "found only $count README commands to run"
while IFS= read -r line; do
  (cd "$work" && eval "$line" >/dev/null 2>"$work/err") || fail "README command failed: $line: $(cat "$work/err")"
done <<<"$commands"
[ -s "$work/sandpic.png" ] && [ -s "$work/desert-2.png" ] && [ -s "$work/stages/3-segmentation.png" ] \
  || fail "the README's commands did not write the pictures they name"
echo "docs: key table current, $count README commands ran"
