#!/bin/sh
# Rebuilds the reference files of this directory: run from it, with Debian's libosd-dev 3.5.0.
set -e
g++ -O2 limit_oracle.cpp -losdCPU -o /tmp/limit_oracle
for f in ../*.obj.gz; do
    b=$(basename "$f" .obj.gz)
    case $b in loop_*) s=loop;; bilinear_*) s=bilinear;; *) s=catmark;; esac
    skip=
    # OpenSubdiv 3.5.0 crashes on these faces (fixed in 3.6.0, commit 51eb6a04).
    [ "$b" = catmark_val2_interior ] && skip=48,49
    zcat "$f" > "/tmp/$b.obj"
    /tmp/limit_oracle "/tmp/$b.obj" "$b.limit.txt" $s 2 6 $skip
    gzip -9 -n -f "$b.limit.txt"
    rm "/tmp/$b.obj"
done
