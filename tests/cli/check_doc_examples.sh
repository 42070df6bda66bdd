#!/usr/bin/env bash
# Runs every `./build/railmodal ...` command of the ```sh blocks of README.md and docs/*.md as
# written (issue 17 item 10), or, given RAILMODAL_MPI_EXE, every `mpirun ...
# build/tools/mpi/railmodal-mpi ...` one: each must exit 0 and print nothing on stderr (no
# deprecation note, no error). It runs in a scratch folder where data/ and the programs are
# links, so that the files the examples write with -o land there and their relative paths hold.
# Usage: check_doc_examples.sh SOURCE_DIR RAILMODAL_EXE SCRATCH_DIR [RAILMODAL_MPI_EXE]
# DOC_EXAMPLES_SKIP, if set, names a file of commands (whole lines, as the docs write them; '#'
# starts a comment) that are not run: the sanitized build's list (tests/cli/CMakeLists.txt).
set -euo pipefail
src=$1 exe=$2 work=$3 mpi_exe=${4:-}
rm -rf "$work"
mkdir -p "$work/build/tools/mpi"
ln -s "$src/data" "$work/data"
ln -s "$exe" "$work/build/railmodal"
pattern='^\./build/railmodal '
if [ -n "$mpi_exe" ]; then
  ln -s "$mpi_exe" "$work/build/tools/mpi/railmodal-mpi"
  pattern='^mpirun .*build/tools/mpi/railmodal-mpi '
fi
# The lines of the ```sh blocks, continuation lines joined.
mapfile -t commands < <(awk '/^```sh/ { on = 1; next } /^```/ { on = 0 } on' "$src/README.md" "$src"/docs/*.md |
  sed -e ':a' -e '/\\$/N; s/\\\n */ /; ta' | grep "$pattern")
[ "${#commands[@]}" -gt 0 ] || { echo "no examples match '$pattern'"; exit 1; }
skipped=0
skip_list=()
if [ -n "${DOC_EXAMPLES_SKIP:-}" ]; then
  mapfile -t skip_list < <(grep -v -e '^#' -e '^[[:space:]]*$' "$DOC_EXAMPLES_SKIP")
fi
failed=0
for command in "${commands[@]}"; do
  for s in "${skip_list[@]}"; do
    [ "$s" = "$command" ] && { skipped=$((skipped + 1)); continue 2; }
  done
  code=0
  (cd "$work" && bash -c "$command" >/dev/null 2>"$work/stderr") || code=$?
  if [ "$code" != 0 ] || [ -s "$work/stderr" ]; then
    echo "FAILED (exit $code): $command"
    cat "$work/stderr"
    failed=1
  fi
done
echo "$((${#commands[@]} - skipped)) documented commands run ($skipped left out: $(basename "${DOC_EXAMPLES_SKIP:-none}"))"
[ -n "$mpi_exe" ] && exit $failed

# The example outputs: a ``` block whose first line is `$ railmodal ARGS` shows what ARGS print.
# Each of its other lines must be a line of the real output, in order; a block may leave lines
# out ("..." on a line of its own) and cut a line short ("..." at its end: the line starts so),
# but must show at least one line: a block with none would check nothing.
mkdir "$work/blocks"
awk -v dir="$work/blocks" '
  /^```/ {
    if (block) { block = 0; if (inside) { inside = 0; close(file) } } else { block = 1; opening = 1 }
    next
  }
  opening { opening = 0; if ($0 ~ /^\$ railmodal /) { inside = 1; file = dir "/" ++n } }
  inside { print > file }' "$src/README.md" "$src"/docs/*.md
blocks=0
for block in "$work"/blocks/*; do
  [ -e "$block" ] || continue
  blocks=$((blocks + 1))
  command="./build/$(head -n 1 "$block" | cut -c3-)"
  if ! tail -n +2 "$block" | grep -qv -e '^[[:space:]]*$' -e '^\.\.\.$'; then
    echo "EMPTY EXPECTED OUTPUT: the block of $command shows no line of what it prints"
    failed=1
    continue
  fi
  (cd "$work" && bash -c "$command" 2>/dev/null | sed 's/[[:space:]]*$//' >"$work/actual") || true
  mapfile -t got <"$work/actual"
  i=0
  while IFS= read -r line; do
    [ "$line" = "..." ] && continue
    prefix=${line%...}
    while [ $i -lt ${#got[@]} ]; do
      if [ "$prefix" != "$line" ]; then [[ "${got[$i]}" == "$prefix"* ]] && break
      elif [ "${got[$i]}" = "$line" ]; then break; fi
      i=$((i + 1))
    done
    if [ $i -ge ${#got[@]} ]; then
      echo "OUTPUT DIFFERS: $command prints no line (in this order) like:"
      echo "  $line"
      failed=1
      break
    fi
    i=$((i + 1))
  done < <(tail -n +2 "$block" | sed 's/[[:space:]]*$//')
done
echo "$blocks documented outputs checked"
exit $failed
