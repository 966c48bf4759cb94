#!/bin/sh
# The compiler launcher when ccache is used (cmake/A6FastBuild.cmake):
#
#   sh cmake/ccache-pch.sh ENV_ASSIGNMENTS... CCACHE COMPILER ARGS...
#
# runs the compile through ccache and, when it writes a precompiled header (-o FILE.gch), writes
# FILE.gch.sum beside it: its checksum, which ccache hashes instead of the header itself
# (its pch_external_checksum). A precompiled header is 80 to 90 MB; every compile that
# uses it would otherwise read and hash all of it, even when the cache already holds its object.
# The sum is removed before the header is written and written only once the header is whole, in
# the same build step, so no compile that uses the header can see an old sum.
out=""
prev=""
for arg in "$@"; do
  [ "$prev" = "-o" ] && out="$arg"
  prev="$arg"
done
case "$out" in
  *.gch) rm -f "$out.sum" ;;
  *) exec "$@" ;;
esac
"$@" || exit
sum=$(md5sum <"$out") || exit
printf '%s\n' "$sum" >"$out.sum"
