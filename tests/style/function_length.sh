#!/usr/bin/env bash
# Fails when a function in the given folders is longer than MAX lines, counted from the first line of its
# signature to its closing brace. Relies on the project's clang-format style: a function body's opening
# brace stands alone on its line (BraceWrapping AfterFunction), its closing brace at the same indent.
#   function_length.sh MAX FOLDER...
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 MAX FOLDER..." >&2; exit 2; }
max=$1
shift
cd "$(dirname "$0")/../.."
mapfile -t files < <(git ls-files --cached --others --exclude-standard -- "${@/%//*.cpp}" "${@/%//*.hpp}")
[ ${#files[@]} -gt 0 ] || { echo "function_length: no sources in $*" >&2; exit 2; }
awk -v max="$max" '
  FNR == 1 { open = "" }
  { line[FNR] = $0 }
  # A body opens: a line that is only "{" (statements open theirs at the end of their own line).
  /^[ ]*\{$/ && open == "" {
    indent = $0; sub(/\{$/, "", indent)
    start = FNR - 1
    # Walk up over the signature: stop at a blank line, a comment, or the end of a previous statement.
    while (start > 1) {
      previous = line[start - 1]
      if (previous ~ /^[ ]*$/ || previous ~ /^[ ]*\/\// || previous ~ /[;{}][ ]*$/ || previous ~ /^[ ]*(public|private|protected):/ || previous ~ /^#/) break
      start--
    }
    open = indent "}"; open_line = start; signature = line[start]
    next
  }
  open != "" && $0 == open {
    length_lines = FNR - open_line + 1
    if (length_lines > max) {
      printf "%s:%d: function of %d lines (more than %d): %s\n", FILENAME, open_line, length_lines, max, signature
      bad++
    }
    open = ""
  }
  END { if (bad > 0) { exit 1 } }
' "${files[@]}" && echo "function_length: no function over $max lines in ${#files[@]} files of $*"
