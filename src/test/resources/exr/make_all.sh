#!/bin/sh
# Remakes every test image of this folder (see README.md): python3 writes the scanline files,
# the Debian openexr tools (exrmaketiled, exr2aces) the tiled ones and the scanline PIZ one;
# each is then gzipped (the tests unzip them).
set -e
rm -f *.exr *.exr.gz
python3 make_exr.py
for c in rle zip; do exrmaketiled -t 16 8 -z $c scan-none.exr tiled-$c.exr; done
exrmaketiled -m -t 16 8 -z zip scan-none.exr mipmap-zip.exr
exrmaketiled -t 16 8 -z zip window-none.exr window-tiled-zip.exr
# PIZ does not pay on small tiles of the noisy image: its tiles are all stored raw.
exrmaketiled -t 32 16 -z piz scan-none.exr tiled-piz-stored.exr
# The quantised "steps" images do compress, in full and partial tiles (64 = 24 + 24 + 16).
exrmaketiled -t 24 12 -z piz steps-none.exr tiled-steps-piz.exr
exrmaketiled -t 24 12 -z piz steps-float-zip.exr tiled-steps-float-piz.exr
exrmaketiled -t 24 12 -z piz steps-uint-zip.exr tiled-steps-uint-piz.exr
exrmaketiled -t 24 12 -z piz steps-luminance-none.exr tiled-steps-luminance-piz.exr
exrmaketiled -t 128 128 -z piz wide-float-none.exr tiled-wide-float-piz.exr
# exr2aces writes scanline PIZ (and converts the colours to ACES primaries); its NONE twin is the reference.
exr2aces steps-zip.exr scan-steps-piz.exr
exrmaketiled -t 16 8 -z none scan-steps-piz.exr scan-steps-piz-reference.exr
# Lossy codecs, only for the refusal message: the header and the start of the offset table.
exrmaketiled -t 16 8 -z dwab scan-none.exr full.exr && head -c 420 full.exr > tiled-dwab.exr
exrmaketiled -t 16 8 -z pxr24 scan-none.exr full.exr && head -c 420 full.exr > tiled-pxr24.exr
rm full.exr scan-float-none.exr steps-zip.exr wide-float-none.exr
gzip -9n *.exr
