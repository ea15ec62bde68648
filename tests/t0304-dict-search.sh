#!/bin/sh
test_description='dict-learn start and local search: greedy k-means++ and split/merge vs the plain method on facecap and the elephant walk'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/dict-lib.sh"

test_expect_success 'bad --start and --search are usage errors' '
	test_must_fail_usage dict-learn --start random /dev/null 2>err &&
	grep "start" err &&
	test_must_fail_usage dict-learn --search -1 /dev/null &&
	test_must_fail_usage dict-learn --search x /dev/null
'

need_shared_data anim/facecap-335.tar.xz

test_expect_success 'setup: facecap OBJ frames -> lower and upper parts; elephant walk' '
	facecap_parts --raw &&
	if [ -r "$SHARED_DATA/anim/elephant-walk-457.tar.xz" ]; then
		mkdir el && tar -xJf "$SHARED_DATA/anim/elephant-walk-457.tar.xz" -C el &&
		mesh-import --raw "el/*/frame_*.obj" >eleph.mesh && rm -rf el
	fi
'
# energy of the default (greedy start + search) never above the plain
# method's (k-means++ start, block coordinate descent), same seed and restarts
cmp_energy() { # file d lambda
	dict-learn -d $2 --lambda $3 --seed 3 --report new.rep "$1" >/dev/null &&
	dict-learn -d $2 --lambda $3 --seed 3 --start kmeans++ --search 0 --report old.rep "$1" >/dev/null &&
	e=$(awk "/^energy /{print \$2}" new.rep) && o=$(awk "/^energy /{print \$2}" old.rep) &&
	echo "$1 d=$2 lambda=$3: search $e plain $o" >>"$TRASH/energies" &&
	test_le "$e" "$o"
}
test_expect_success 'facecap parts d=20 lambda=0 and 2: search <= plain' '
	cmp_energy part_0.mesh 20 0 && cmp_energy part_1.mesh 20 0 && cmp_energy part_1.mesh 20 2
'
test_expect_success 'facecap upper part d=50 lambda=2, d=150 lambda=0: search <= plain' '
	cmp_energy part_0.mesh 50 2 && cmp_energy part_0.mesh 150 0
'
if [ -r "$SHARED_DATA/anim/elephant-walk-457.tar.xz" ]; then
	test_expect_success 'elephant walk d=50 lambda=0: search <= plain' '
		cmp_energy eleph.mesh 50 0
	'
fi
[ -s "$TRASH/energies" ] && sed "s/^/# /" "$TRASH/energies"
test_expect_success 'report energy equals the model energy of the search (-v)' '
	dict-learn -v -d 30 --lambda 0 --report r.rep part_0.mesh 2>log >/dev/null &&
	m=$(sed -n "s/.*d 30: energy \([^ ]*\).*/\1/p" log) && e=$(awk "/^energy /{print \$2}" r.rep) &&
	test_near "$m" "$e" "$(awk -v e="$e" "BEGIN{print 1e-8 * e}")"
'
test_done
