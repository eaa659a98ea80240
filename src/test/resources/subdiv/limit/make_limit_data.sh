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

# Raised approximation levels, on irregular shapes only: (smooth, sharp) = (4, 6) and (8, 8), a
# few irregular faces each, three points a face (see README.md).
FACES=5
for b in catmark_cube catmark_pole8 catmark_nonquads catmark_smoothtris0 catmark_xord_boundary catmark_dart_edgecorner \
         catmark_cube_creases1 catmark_cubes_semisharp catmark_chaikin1 catmark_pyramid_creases1 catmark_fan catmark_gregory_test6 \
         loop_cube loop_pole8 loop_xord_boundary loop_cube_creases1 loop_icos_semisharp; do
    case $b in loop_*) s=loop;; *) s=catmark;; esac
    zcat "../$b.obj.gz" > "/tmp/$b.obj"
    for levels in "4 6" "8 8"; do
        set -- $levels
        out="$b.approx$1_$2.txt"
        /tmp/limit_oracle "/tmp/$b.obj" "$out" $s $1 $2 - $FACES
        gzip -9 -n -f "$out"
    done
    rm "/tmp/$b.obj"
done
