#!/bin/sh
# Fails when docs/scene-reference.md differs from what the binary generates from the declared
# parameters (regenerate: build/arksph scene-reference > docs/scene-reference.md).
set -eu
binary=$1
reference=$(dirname "$0")/../docs/scene-reference.md
if "$binary" scene-reference | diff -u "$reference" - ; then
  echo "docs/scene-reference.md is current"
else
  echo "docs/scene-reference.md is stale: regenerate it with: $binary scene-reference > docs/scene-reference.md" >&2
  exit 1
fi
