#!/bin/sh
test_description='seg-graphcut --symmetric on scanned faces (Spacetime Faces: neutral, smile, disgust, surprise)'
. "$(dirname "$0")/test-lib.sh"
need_shared_data faces/neutral.ply

asym() { sed -n 's/.*seam asymmetry: Hausdorff distance to its mirror \([^%]*\)%.*/\1/p' "$1"; }

# the face looks along z with its chin towards +x; forehead and chin seeds,
# then the same seeds moved 25 mm to either side
test_expect_success 'setup: four expressions as one animation' '
	F="$SHARED_DATA/faces" &&
	mesh-import --raw "$F/neutral.ply" "$F/smile.ply" "$F/disgust.ply" "$F/surprise.ply" >st.mesh &&
	printf "0 -30 -26 1300\n1 160 -26 1300\n" >mid.seeds &&
	printf "0 -30 0 1300\n1 150 -50 1300\n" >off.seeds
'
test_expect_success 'the plane is found; the seam becomes symmetric to about the scan'\''s own asymmetry' '
	seg-graphcut -v --seed-snap 0.5 --seeds mid.seeds --symmetric st.mesh >s.lab 2>s.err &&
	plane=$(sed -n "s/.*mirror plane \([^ ]*\) (found).*/\1/p" s.err) && test -n "$plane" &&
	seg-graphcut -v --seed-snap 0.5 --seeds mid.seeds --mirror "$plane" st.mesh >p.lab 2>p.err &&
	seg-graphcut -v --seed-snap 0.5 --seeds off.seeds --mirror "$plane" st.mesh >po.lab 2>po.err &&
	seg-graphcut -v --seed-snap 0.5 --seeds off.seeds --symmetric st.mesh >so.lab 2>so.err &&
	b=$(asym p.err) && a=$(asym s.err) && bo=$(asym po.err) && ao=$(asym so.err) &&
	echo "Spacetime faces seam asymmetry (% diagonal): seeds in the middle $b -> $a, seeds off the middle $bo -> $ao" >"$TRASH/fig" &&
	test_le 5 "$b" && test_le "$a" 2 && test_le 5 "$bo" && test_le "$ao" 2
'
[ -s "$TRASH/fig" ] && say "# $(cat "$TRASH/fig")"
test_done
