# morph2d-lib.sh -- shared helpers of the 2D morphing tests (t05xx).

# bar_pair RES: MESH of 2 frames: a 1 x 0.2 bar and the bar rotated by 90 degrees
bar_pair() {
	mesh-gen -n "$1" -m 2 grid | awk '
	/^frames /{ print "frames 2"; next }
	/^frame /{ print "frame 0"; inframe = 1; next }
	inframe && NF == 3 { X[n] = $1; Y[n] = $2 * 0.2; printf "%.17g %.17g 0\n", X[n], Y[n]; n++; next }
	{ print }
	END { print "frame 1"; for (i = 0; i < n; i++) printf "%.17g %.17g 0\n", -Y[i], X[i] }'
}

# bend_pair TH SQ: a 4 x 0.4 bar, and the bar bent by angle TH with its
# thickness scaled by SQ
bend_pair() {
	mesh-gen -n 40 -m 2 grid | awk -v th="$1" -v sq="$2" '
	/^frames /{ print "frames 2"; next }
	/^frame /{ print "frame 0"; inframe = 1; next }
	inframe && NF == 3 { X[n] = $1 * 4; Y[n] = $2 * 0.4; printf "%.17g %.17g 0\n", X[n], Y[n]; n++; next }
	{ print }
	END { print "frame 1"; r = 4 / th;
	      for (i = 0; i < n; i++) printf "%.17g %.17g 0\n", (r - sq * Y[i]) * sin(X[i] / r), r - (r - sq * Y[i]) * cos(X[i] / r) }'
}

# smallest signed triangle area over all frames of a plain MESH stream
min_area() {
	awk '$1 == "f" { F[nfa++] = $2 " " $3 " " $4 }
	     $1 == "frame" { k = 0; fr++; next }
	     fr > 0 && NF == 3 { X[fr, k] = $1; Y[fr, k] = $2; k++ }
	     END { m = 1e300; for (f = 1; f <= fr; f++) for (t = 0; t < nfa; t++) {
		split(F[t], v, " "); a = v[1]; b = v[2]; c = v[3];
		s = (X[f,b]-X[f,a])*(Y[f,c]-Y[f,a]) - (Y[f,b]-Y[f,a])*(X[f,c]-X[f,a]);
		if (s < m) m = s }; print m }' "$1"
}
