#!/usr/bin/env bash
# Fills fuzz/corpus/parse_eval and fuzz/corpus/render with the seed corpus: the
# scenes of tests/fixtures and examples, their include files, the standard
# include files and fuzz/seeds. Files are named by the SHA-1 of their contents
# (as libFuzzer names its own), so running it again adds only what changed.
set -euo pipefail
cd "$(dirname "$0")/.."
for target in parse_eval render; do
  mkdir -p "fuzz/corpus/$target"
done
n=0
while IFS= read -r -d '' f; do
  sum=$(sha1sum "$f" | cut -d' ' -f1)
  for target in parse_eval render; do
    cp "$f" "fuzz/corpus/$target/$sum"
  done
  n=$((n + 1))
done < <(find tests/fixtures examples src/stdlib fuzz/seeds -type f \
  \( -name '*.rts' -o -name '*.inc' -o -name '*.pov' \) -print0 | sort -z)
echo "seed corpus: $n files in fuzz/corpus/{parse_eval,render}"
