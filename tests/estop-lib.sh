# estop-lib.sh -- shared helpers of the E-StopMotion tests (t04xx).

# camel_scans K...: cK.mesh, the shared camel gallop scan K (01..05)
# imported and cleaned by mesh-clean, for each K
camel_scans() {
	for k in "$@"; do
		mesh-import "$SHARED_DATA/scans/camel-gallop-$k.off" | mesh-clean >c$k.mesh 2>/dev/null || return 1
	done
}

# cow_walk: w0.mesh, the shared cow, and steps.mesh, 9 frames of it
# walking a step (clay-deform -m arap: a front hoof forward, a hind hoof
# back, the snout down; frame 0 the cow itself)
cow_walk() {
	mesh-import "$SHARED_DATA/meshes/cow.off" >w0.mesh &&
	printf "%s\n" "2476 0.32 -0.17 0.091709" "2433 -0.55 -0.25 -0.105921" "890 0.47 -0.06 -0.010733" \
		"2735 -0.56 -0.02 0.17" "2394 0.13028 -0.314633 -0.091709" "2515 -0.369903 -0.319838 0.105921" \
		"408 -0.004231 0.217953 0.0" >pose.lm &&
	clay-deform -m arap -n 8 -l pose.lm --poses steps.mesh w0.mesh >/dev/null
}

# egg_spheres: s3.mesh and s4.mesh, unit icospheres of subdivision levels 3
# and 4: the connectivities of the generated source and target eggs below
egg_spheres() {
	mesh-gen -s 3 icosphere >s3.mesh && mesh-gen -s 4 icosphere >s4.mesh
}

# egg_pair A: src.mesh, the nosed egg on s3.mesh, and g.mesh, the egg on
# the finer s4.mesh with its upper part turned by A (egg_spheres first)
egg_pair() {
	nosed_egg s3.mesh 0 >src.mesh && nosed_egg s4.mesh "$1" >g.mesh
}

# nricp options of one registration on the generated eggs: no choice of
# start, pass, release or rest (t0429, t0431)
NRICP_ONE="-k 4 --fit 6 --passes 1 --start none --fit-release stay --fit-smooth-retry 0"

# nosed_egg MESH A: MESH (a unit icosphere) made an egg with a nose, its
# upper part turned by A radians about y (t0416, t0425)
nosed_egg() {
	awk -v a="$2" '/^frame [0-9]/ { on = 1; print; next }
	on && NF == 3 { x = 0.35 * $1; y = 0.2 * $2; z = $3
		if (x > 0) x += 0.25 * x / 0.35 * exp(-((z - 0.4)^2 + y^2) / 0.04)
		s = (z + 0.1) / 0.3; s = s < 0 ? 0 : s > 1 ? 1 : s; t = a * s * s * (3 - 2 * s)
		zz = z + 0.1; xx = x * cos(t) - zz * sin(t); zz = x * sin(t) + zz * cos(t)
		printf "%.17g %.17g %.17g\n", xx, y, zz - 0.1; next }
	{ print }' "$1"
}

# test_kernel K FLAG TITLE BODY: BODY with OPENBLAS_CORETYPE=K where
# /proc/cpuinfo has FLAG, else skipped (the registration's nonlinear steps
# turn the last bits in which OpenBLAS's CPU kernels round into other
# poses: nricp(1) REPRODUCIBILITY)
test_kernel() {
	if grep -qw "$2" /proc/cpuinfo 2>/dev/null; then
		test_expect_success "$3 (OPENBLAS_CORETYPE=$1)" "OPENBLAS_CORETYPE=$1 && export OPENBLAS_CORETYPE && $4"
	else
		test_count=$((test_count + 1))
		say "ok $test_count # skip $3 (OPENBLAS_CORETYPE=$1: the CPU has no $2)"
	fi
}
