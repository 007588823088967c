#!/usr/bin/env bash
# The object files of the kernel sets (*_isa_<set>.cpp, include/pbrfit/core/kernel_set.hpp) must define no
# weak code symbol: such a symbol is an inline function (Eigen's, the standard library's) that other files
# define too, compiled here for another instruction set, and the linker keeps one copy for the whole
# program, so generic code could end up running AVX-512 instructions. Shared constant data (u, V) is the
# same bytes in every set and allowed. Each object must also be built for its own instruction set: the
# generic one uses no 256- or 512-bit register, avx2 uses 256-bit ones, avx512 512-bit ones.
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
  set_name=${object##*_isa_}
  set_name=${set_name%%.*}
  code=$(objdump -d --no-show-raw-insn "$object")
  ymm=$(grep -c '%ymm' <<<"$code" || true)
  zmm=$(grep -c '%zmm' <<<"$code" || true)
  case $set_name in
    generic) wanted=$(( ymm == 0 && zmm == 0 )) ;;
    avx2) wanted=$(( ymm > 0 && zmm == 0 )) ;;
    avx512) wanted=$(( zmm > 0 )) ;;
    *) echo "$object: unknown kernel set '$set_name'" >&2; wanted=0 ;;
  esac
  if (( ! wanted )); then
    echo "$object is not built for $set_name: $ymm instructions on 256-bit registers, $zmm on 512-bit ones" >&2
    status=1
  fi
done
(( checked > 0 )) || { echo "kernel_set_objects.sh: no *_isa_*.o among the objects given" >&2; exit 1; }
echo "kernel_set_objects.sh: $checked kernel set object(s), each for its instruction set, no shared inline code"
exit $status
