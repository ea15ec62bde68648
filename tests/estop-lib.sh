# estop-lib.sh -- shared helpers of the E-StopMotion tests (t04xx).

# camel_scans K...: cK.mesh, the shared camel gallop scan K (01..05)
# imported and cleaned by mesh-clean, for each K
camel_scans() {
	for k in "$@"; do
		mesh-import "$SHARED_DATA/scans/camel-gallop-$k.off" | mesh-clean >c$k.mesh 2>/dev/null || return 1
	done
}
