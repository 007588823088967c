#!/usr/bin/env bash
# pbrfit finds its shared files (data, report package, batch template) at run time, nothing compiled in:
# a copy of the binary under a prefix reads <prefix>/share/pbrfit, PBRFIT_SHARE_DIR and PBRFIT_DATA_DIR
# override it, and a binary with neither says so on one line (exit 3) instead of reading the build tree.
source "$(dirname "$0")/lib/common.bash"

mkdir -p prefix/bin
cp "$PBRFIT" prefix/bin/pbrfit
PBRFIT=$WORK/prefix/bin/pbrfit
src=$PBRFIT_SOURCE_DIR

note "no share/pbrfit beside the copied binary: one line, exit 3"
run_pbrfit submit --dry-run "$src/jobs/quickstart.yaml"
expect_status 3 "no shared files"
[[ $(wc -l <err.txt) -eq 1 ]] || { cat err.txt; fail "not exactly one line on stderr"; }
grep -q "shared files are not installed" err.txt || { cat err.txt; fail "the error does not say what is missing"; }
grep -q "$WORK/prefix/share/pbrfit" err.txt || { cat err.txt; fail "the error does not name the places looked at"; }

note "<prefix>/share/pbrfit holds the batch template"
mkdir -p prefix/share/pbrfit
cp "$src/cluster/sbatch.template" prefix/share/pbrfit/
run_pbrfit submit --dry-run "$src/jobs/quickstart.yaml"
expect_status 0 "submit with an installed template"
grep -q '^#SBATCH' out.txt || fail "no batch script printed"

note "PBRFIT_SHARE_DIR names another folder"
mkdir -p elsewhere
sed 's/^#SBATCH --job-name=/#SBATCH --comment=from-elsewhere\n&/' "$src/cluster/sbatch.template" >elsewhere/sbatch.template
PBRFIT_SHARE_DIR=$WORK/elsewhere run_pbrfit submit --dry-run "$src/jobs/quickstart.yaml"
expect_status 0 "submit with PBRFIT_SHARE_DIR"
grep -q 'from-elsewhere' out.txt || fail "PBRFIT_SHARE_DIR's template was not used"

note "materials come from the data directory: missing under the prefix, found with PBRFIT_DATA_DIR"
run_pbrfit validate "$src/jobs/merl-metals-quick.yaml"
expect_status 2 "validate without the stand-ins"
[[ $(wc -l <err.txt) -eq 1 ]] || { cat err.txt; fail "not exactly one line on stderr"; }
grep -q "$WORK/prefix/share/pbrfit/data/merl_nbrdf" err.txt || { cat err.txt; fail "the error does not name the data directory"; }
PBRFIT_DATA_DIR=$src/data run_pbrfit validate "$src/jobs/merl-metals-quick.yaml"
expect_status 0 "validate with PBRFIT_DATA_DIR"
echo "PASS"
