#!/usr/bin/env bash
# Checks the documentation as a reader would meet it:
#   1. every relative link in README.md, ARCHITECTURE.md, CHANGELOG.md and
#      docs/ resolves to a file in the repository;
#   2. every command in a fenced `sh` block of docs/getting-started.md and
#      docs/study.md runs from the repository root and exits 0;
#   3. `cargo doc --no-deps` prints no warning.
# Run from anywhere; `.ci/test` runs it after the tests. `--links` does 1 only.
set -euo pipefail
cd "$(dirname "$0")/.."

failed=0
pages=(README.md ARCHITECTURE.md CHANGELOG.md)
while IFS= read -r page; do pages+=("$page"); done < <(find docs -name '*.md' | sort)

# 1. Links: [text](target) and ![alt](target), outside fenced code blocks.
for page in "${pages[@]}"; do
  dir="$(dirname "$page")"
  while IFS= read -r target; do
    path="${target%%#*}"
    [ -z "$path" ] && continue
    if [ ! -e "$dir/$path" ]; then
      echo "check-docs: $page links to $target, which does not exist" >&2
      failed=1
    fi
  done < <(perl -ne '
      $fence = !$fence if /^\s*```/;
      next if $fence;
      while (/!?\[[^\]]*\]\(([^)\s]+)\)/g) {
        my $t = $1;
        print "$t\n" unless $t =~ m{^(?:[a-z]+:|#)};
      }' "$page")
done
if [ "$failed" -ne 0 ]; then exit 1; fi
echo "check-docs: links in ${#pages[@]} pages resolve" >&2
if [ "${1:-}" = "--links" ]; then exit 0; fi

# 2. The guide's commands, block by block, as a reader would paste them.
for page in docs/getting-started.md docs/study.md; do
  n=0
  while IFS= read -r -d '' block; do
    n=$((n + 1))
    echo "check-docs: $page, sh block $n" >&2
    if ! (unset DISPLAY WAYLAND_DISPLAY; bash -euo pipefail -c "$block") >/dev/null; then
      echo "check-docs: $page: sh block $n failed:" >&2
      echo "$block" >&2
      exit 1
    fi
  done < <(perl -ne '
      if (/^```sh\s*$/) { $in = 1; $b = ""; next }
      if ($in && /^```/) { $in = 0; print "$b\0"; next }
      $b .= $_ if $in;' "$page")
  echo "check-docs: $page: $n sh blocks ran" >&2
done

# 3. rustdoc: no warnings (broken intra-doc links, bad HTML, ...).
warnings="$(cargo doc --no-deps --locked 2>&1 | grep -c '^warning' || true)"
if [ "$warnings" -ne 0 ]; then
  cargo doc --no-deps --locked 2>&1 | grep -A8 '^warning' >&2
  echo "check-docs: cargo doc printed $warnings warnings" >&2
  exit 1
fi
echo "check-docs: cargo doc --no-deps has no warnings" >&2
