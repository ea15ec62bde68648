# dict-lib.sh -- helpers for the dict-learn tests (t0304-t0319), sourced
# after test-lib.sh.

# facecap_parts [RAW]: facecap's OBJ frames (6 decimals) -> face.mesh and
# its two parts part_0.mesh (upper) and part_1.mesh (lower: faces whose
# centroid lies below 75% of the average face's height, as t0301 cuts it);
# RAW = --raw writes them raw.
facecap_parts() {
	mkdir fc && tar -xJf "$SHARED_DATA/anim/facecap-335.tar.xz" -C fc &&
	mesh-import --raw "fc/*/frame_*.obj" >face.mesh && rm -rf fc &&
	anim-avg face.mesh >avg.mesh &&
	awk -v frac=0.75 -f "$TEST_DIRECTORY/lower-part.awk" avg.mesh >part.lab &&
	part-split -l part.lab -o "part_%d.mesh" ${1:-} face.mesh
}

# noisy_head FRAMES SEED NOISE_SEED AXES [HEAD-GEN OPTIONS]: head-gen's
# FRAMES-frame head (head.mesh) and a full-rank copy noisy.mesh, uniform
# noise of +-5e-4 on x (AXES = x) or on x and y (AXES = xy), printed with 6
# decimals.
noisy_head() {
	head-gen -f $1 --seed $2 ${5:-} >head.mesh &&
	if [ "$4" = xy ]; then y='$2 + 1e-3 * (rand() - 0.5)'; else y='$2'; fi &&
	awk "BEGIN { srand($3) } /^frame /{ fr = 1 } fr && NF == 3 && \$1 != \"frame\" { printf \"%.6f %.6f %.6f\n\", \$1 + 1e-3 * (rand() - 0.5), $y, \$3; next } { print }" head.mesh >noisy.mesh &&
	mesh-info noisy.mesh | grep "^frames $1\$"
}

# threads_agree TAG "OPTIONS" N...: dict-learn OPTIONS on noisy.mesh with
# --threads N for each N (TAG<N>.lib, .lab, .rep, stderr in TAG<N>.log);
# the library, labels and report of every N are the first N's, byte for byte
threads_agree() {
	tag=$1 opts=$2 && shift 2 && first= &&
	for n in "$@"; do
		dict-learn $opts --threads $n --report $tag$n.rep --labels-out $tag$n.lab noisy.mesh >$tag$n.lib 2>$tag$n.log ||
			return 1
		if [ -z "$first" ]; then first=$n
		else test_cmp $tag$first.lib $tag$n.lib && test_cmp $tag$first.lab $tag$n.lab &&
			test_cmp $tag$first.rep $tag$n.rep || return 1
		fi
	done
}
