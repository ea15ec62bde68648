# t0604-u.awk -- a U of two arms (1 wide, 4 high) on a base 1 high, the
# notch between the arms g wide, n outline points a unit, counter-clockwise
# from the bottom left corner:
#   awk -v g=1 [-v n=4] -f t0604-u.awk >u.rings
BEGIN { if (!n) n = 4; if (!g) g = 1; w = 2 + g
	print "ring " (n * (18 + 2 * g))
	for (i = 0; i < w * n; i++) print i / n, 0               # base, left to right
	for (i = 0; i < 4 * n; i++) print w, i / n               # right arm, outer side, up
	for (i = 0; i < n; i++) print w - i / n, 4               # right arm top
	for (i = 0; i < 3 * n; i++) print w - 1, 4 - i / n       # right arm, inner side, down
	for (i = 0; i < g * n; i++) print w - 1 - i / n, 1       # the notch's floor
	for (i = 0; i < 3 * n; i++) print 1, 1 + i / n           # left arm, inner side, up
	for (i = 0; i < n; i++) print 1 - i / n, 4               # left arm top
	for (i = 0; i < 4 * n; i++) print 0, 4 - i / n           # left arm, outer side, down
}
