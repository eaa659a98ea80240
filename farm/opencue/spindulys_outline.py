#!/usr/bin/env python
"""Submits a Spindulys animation to OpenCue with PyOutline (docs/farm.md).

    python spindulys_outline.py SCENE.dat OUTDIR --frames 1-48 [--chunk 4] [--tiles 1] [--render render]

With --tiles 1 one layer renders whole frames, --chunk contiguous frames per OpenCue frame (one
scene load for all of them). With --tiles N > 1 each frame is split into N bands of rows: N
layers render one band of every frame each, and an assemble layer puts frame F together once
band F of every tile layer is done (frame-by-frame dependencies). Every command prints a
progress line at least every two seconds (--progress plain), so RQD never sees a silent frame,
skips frames a retried frame finished (--skip-existing), and exits non-zero on failure, which
OpenCue shows as a dead frame. Frames go to OUTDIR/NAME_####.png, tiles to OUTDIR/tiles/.
"""

import argparse
import getpass
import os

import outline
import outline.cuerun
import outline.depend
import outline.modules.shell


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene", help="the scene file, on storage every host sees")
    parser.add_argument("outdir", help="where the frames go, on storage every host sees")
    parser.add_argument("--frames", required=True, help="frames A-B of the scene's animation")
    parser.add_argument("--chunk", type=int, default=1, help="whole frames per OpenCue frame (tiles: always 1)")
    parser.add_argument("--tiles", type=int, default=1, help="bands of rows each frame is split into")
    parser.add_argument("--render", default="render", help="the render command on the hosts")
    parser.add_argument("--show", default="testing")
    parser.add_argument("--shot", default="spindulys")
    args = parser.parse_args()

    scene = os.path.abspath(args.scene)
    outdir = os.path.abspath(args.outdir)
    name = os.path.splitext(os.path.basename(scene))[0]
    frames = os.path.join(outdir, name + "_####.png")
    ol = outline.Outline("spindulys_" + name, shot=args.shot, show=args.show, user=getpass.getuser())

    if args.tiles == 1:
        # One command per chunk: RQD replaces #FRAME_START# and #FRAME_END# with the chunk's frames.
        ol.add_layer(outline.modules.shell.Shell(
            "render", range=args.frames, chunk=args.chunk,
            command=[args.render, scene, "--frames", "#FRAME_START#-#FRAME_END#", "-o", frames,
                     "--skip-existing", "--progress", "plain"]))
    else:
        tile_layers = []
        for i in range(1, args.tiles + 1):
            tile = os.path.join(outdir, "tiles", "%s_####.tile_%d_of_%d.png" % (name, i, args.tiles))
            layer = outline.modules.shell.Shell(
                "tile_%d_of_%d" % (i, args.tiles), range=args.frames, chunk=1,
                command=[args.render, scene, "--frame", "#IFRAME#", "--tile", "%d/%d" % (i, args.tiles),
                         "-o", tile, "--skip-existing", "--progress", "plain"])
            ol.add_layer(layer)
            tile_layers.append(layer)
        assemble = outline.modules.shell.Shell(
            "assemble", range=args.frames, chunk=1,
            command=[args.render, "assemble", "--frame", "#IFRAME#",
                     os.path.join(outdir, "tiles", "%s_####.tile_*_of_%d.png" % (name, args.tiles)), "-o", frames])
        for layer in tile_layers:
            assemble.depend_on(layer, outline.depend.DependType.FrameByFrame)
        ol.add_layer(assemble)

    outline.cuerun.launch(ol, use_pycuerun=False)


if __name__ == "__main__":
    main()
