#!/bin/sh
test_description='-o temporaries and spool files (issue 13): mkstemp next to
the target (a planted symlink is never followed), removed on SIGINT,
SIGTERM and SIGHUP; spool files unlinked as soon as they are open; output
name patterns with bounded widths'
. "$(dirname "$0")/test-lib.sh"

# the pid's open files that are named like $2 (/proc/PID/fd links)
has_open() {
	ls -l /proc/$1/fd 2>/dev/null | grep -q "$2"
}
# wait until process $1 holds a file named like $2 open (at most 20 s)
wait_open() {
	i=0
	while ! has_open "$1" "$2"; do
		i=$((i + 1)); [ $i -lt 200 ] || { echo "no open file like $2 in $1" >&2; return 1; }
		sleep 0.1
	done
}

# part.mesh: more than the readers' first 1 MiB block (fread waits for a
# full block), less than the whole stream
test_expect_success 'setup' '
	mesh-gen -f 3 -n 4 cylinder >cyl.mesh &&
	mesh-gen -f 4 -n 100 cylinder >big.mesh &&
	head -c 1300000 big.mesh >part.mesh &&
	mesh-info cyl.mesh | grep "^faces" | cut -d" " -f2 >nf &&
	awk -v n=$(cat nf) "BEGIN { for (i = 0; i < n; i++) print i % 2 }" >labels &&
	mesh-info big.mesh | grep "^faces" | cut -d" " -f2 >nf &&
	awk -v n=$(cat nf) "BEGIN { for (i = 0; i < n; i++) print i % 2 }" >biglabels
'
test_expect_success 'a symlink planted at the old predictable OUT.tmp<pid> is not followed' '
	echo precious >victim &&
	sh -c "ln -s victim out.mesh.tmp\$\$ && exec anim-slice -o out.mesh cyl.mesh" &&
	echo precious >expect && test_cmp expect victim &&
	test_cmp cyl.mesh out.mesh &&
	! ls out.mesh.tmp?????? 2>/dev/null &&
	rm out.mesh.tmp*
'
test_expect_success 'the output gets the usual mode (0666 less the umask), not 0600' '
	(umask 022 && anim-slice -o m.mesh cyl.mesh) && ls -l m.mesh | grep "^-rw-r--r--" &&
	(umask 002 && anim-slice -o m2.mesh cyl.mesh) && ls -l m2.mesh | grep "^-rw-rw-r--"
'
# a writer blocked on a FIFO after its first frame, then a signal (INT and
# HUP reset to default: a background job ignores INT, and a run under nohup
# ignores HUP, which the tools rightly keep ignoring)
for sig in TERM HUP INT; do
test_expect_success "SIG$sig mid-run: no OUT.tmp* left, the target untouched" '
	rm -f fifo && mkfifo fifo && echo old >out.mesh &&
	{ perl -e "\$SIG{INT} = \$SIG{HUP} = \"DEFAULT\"; exec @ARGV" anim-slice -o out.mesh fifo & } &&
	pid=$! &&
	exec 3>fifo && cat part.mesh >&3 &&
	wait_open $pid "out.mesh.tmp" &&
	kill -'$sig' $pid; exec 3>&-
	wait $pid; rc=$?
	echo "exit $rc" && test $rc -gt 128 &&
	echo old >expect && test_cmp expect out.mesh &&
	! ls out.mesh.tmp* 2>/dev/null
'
done
test_expect_success 'a spool of stdin is unlinked while open: nothing left after SIGTERM' '
	mkdir -p tmp && rm -f fifo && mkfifo fifo &&
	{ TMPDIR=$PWD/tmp seam-homog -l biglabels <fifo >/dev/null & } &&
	pid=$! &&
	exec 3>fifo && cat part.mesh >&3 &&
	wait_open $pid "$PWD/tmp/" &&
	ls -l /proc/$pid/fd | grep "$PWD/tmp/" &&
	ls tmp >left && ! test -s left
	kill -TERM $pid; exec 3>&-
	wait $pid
	ls tmp >left && ! test -s left
'
test_expect_success 'a spooled run still gives the same bytes as a file' '
	seam-homog -l labels cyl.mesh >a.mesh &&
	cat cyl.mesh | seam-homog -l labels >b.mesh && test_cmp a.mesh b.mesh &&
	mesh-normalize -q cyl.mesh >n1.mesh && cat cyl.mesh | mesh-normalize -q >n2.mesh && test_cmp n1.mesh n2.mesh
'
test_expect_success 'output patterns: huge or overlong widths are usage errors' '
	test_must_fail_usage part-split -l labels -o "p%2147483648d.mesh" cyl.mesh &&
	test_must_fail_usage part-split -l labels -o "p%0100d.mesh" cyl.mesh &&
	test_must_fail_usage mesh-export -o "f%0100d.obj" cyl.mesh &&
	test_must_fail_usage mesh-export -o "f%d%d.obj" cyl.mesh &&
	! ls p*.mesh f*.obj 2>/dev/null &&
	part-split -l labels -o "q%032d.mesh" cyl.mesh && ls q00000000000000000000000000000001.mesh &&
	mesh-export -o "f%-3d.obj" cyl.mesh && ls "f2  .obj"
'
test_done
