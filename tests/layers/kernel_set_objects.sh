#!/usr/bin/env bash
# The object files of the kernel sets (*_isa_<set>.cpp, include/pbrfit/core/kernel_set.hpp) must define no
# weak code symbol: such a symbol is an inline function (Eigen's, the standard library's) that other files
# define too, compiled here for another instruction set, and the linker keeps one copy for the whole
# program, so generic code could end up running AVX-512 instructions. Shared constant data (u, V) is the
# same bytes in every set and allowed.
#   kernel_set_objects.sh OBJECT...   (every object of a module; those of kernel sets are checked)
set -euo pipefail
checked=0 status=0
for object in "$@"; do
  [[ $object == *_isa_*.o ]] || continue
  checked=$((checked + 1))
  weak=$(nm -C --defined-only "$object" | awk '$2 == "W" || $2 == "w"' || true)
  if [[ -n $weak ]]; then
    echo "$object defines weak code another file may share:" >&2
    echo "$weak" >&2
    status=1
  fi
done
(( checked > 0 )) || { echo "kernel_set_objects.sh: no *_isa_*.o among the objects given" >&2; exit 1; }
echo "kernel_set_objects.sh: $checked kernel set object(s), no shared inline code"
exit $status
