#!/bin/sh
# Rebuilds fvar_limit.txt.gz: run from this directory, with Debian's libosd-dev 3.5.0.
# The shapes are those with Far data here (the ones whose UVs have seams).
set -e
MAX_FACES=${MAX_FACES:-40}
g++ -O2 fvar_limit_oracle.cpp -losdCPU -o /tmp/fvar_limit_oracle
out=/tmp/fvar_limit.txt
echo "# OpenSubdiv 3.5.0 Bfr face-varying limit (InitFaceVaryingSurface, approximation levels 2 and 6), modes 0..5; see README.md" > $out
for f in *.fvar0.L2.txt.gz; do
    b=${f%.fvar0.L2.txt.gz}
    case $b in loop_*) s=loop;; bilinear_*) s=bilinear;; *) s=catmark;; esac
    skip=
    # OpenSubdiv 3.5.0 crashes on these faces (fixed in 3.6.0, commit 51eb6a04).
    [ "$b" = catmark_val2_interior ] && skip=48,49
    zcat "../$b.obj.gz" > "/tmp/$b.obj"
    /tmp/fvar_limit_oracle "/tmp/$b.obj" $s $MAX_FACES $skip >> $out
    rm "/tmp/$b.obj"
done
echo "end 0" >> $out
gzip -9 -n -c $out > fvar_limit.txt.gz
