#!/bin/sh
# deps.sh NAME... -- the libcommon sources (base names) that NAME.c/.cpp
# need: the closure over '#include "X.h"' where libcommon/X.c or X.cpp
# exists.  Keeps the fuzz build to the readers and what they call.
cd "$(dirname "$0")/../../libcommon" || exit 1
todo="$*" done=""
while [ -n "$todo" ]; do
    set -- $todo
    n=$1; shift; todo="$*"
    case " $done " in *" $n "*) continue ;; esac
    f=""; [ -f "$n.c" ] && f="$n.c"; [ -f "$n.cpp" ] && f="$n.cpp"
    [ -n "$f" ] || continue
    done="$done $n"
    for h in $(sed -n 's/^#include "\([a-z0-9_]*\)\.h".*/\1/p' "$f"); do
        todo="$todo $h"
    done
done
echo $done
