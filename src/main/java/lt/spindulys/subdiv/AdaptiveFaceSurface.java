package lt.spindulys.subdiv;

/**
 * The limit surface of any face of Catmull-Clark or Loop with a limit surface (regular or not),
 * by feature-adaptive descent, as OpenSubdiv's Bfr builds its patch tree (with its default
 * approximation levels, 2 for smooth and 6 for sharp features, given to the constructor). The
 * sub-face containing (u,v) is followed down the refined levels until it is a regular patch
 * ({@link FaceSurface#isRegular(Level, SubdivOptions, int, boolean)} with infinitely sharp edges
 * as patch boundaries, Far's inf-sharp patches), whose B-spline or box-spline patch is evaluated
 * (exact: a regular patch's sub-patches are the same polynomial pieces, so a regular region gives
 * the same values at whatever depth it is found). Sub-faces that stay irregular end, as in Far's
 * adaptive refinement, at the smooth level unless a sharp feature (semi-sharp edge or vertex,
 * irregular inf-sharp corner, non-manifold vertex) is at a corner, and at the sharp level in any
 * case; there the end patch is Far's Gregory patch ({@link GregoryPatch}, {@link GregoryTriangle}).
 * N-gons of Catmull-Clark start at their level-1 quads, one per Bfr sub-face.
 *
 * <p>The descent is made once per sub-face, where an evaluation first needs it: a sub-face still
 * irregular keeps its level (cut down around it) until a point falls in it; then that level is
 * refined once and cut down to the one-rings of its children (as {@link PatchRefiner} prunes its
 * levels: their refinements are exact), and the children are settled as patches or kept for
 * refining in turn. So only sub-faces that (u,v) values descend into are refined, each only as
 * deep as it needs (level 2 where no sharp feature remains). Regular and end patches stay in a
 * tree of sub-faces; once the tree is built where the points fall, an evaluation is the walk down
 * it and its patch's basis, allocating nothing. An evaluator has scratch space and a tree of its
 * own: one thread at a time.
 *
 * <p>The same descent gives a face's face-varying (UV) limit surface ({@link #ofFaceVarying}):
 * each level is refined with its UV value mesh ({@link FaceVarying}), whose topology (seams as
 * boundaries, values pinned by the face-varying option) and UVs replace the level's own for
 * deciding and building the patches, as Bfr's face-varying surfaces are the vertex surfaces of
 * that topology.
 */
final class AdaptiveFaceSurface {
    /** A sub-face: its corners' locations in the face's (u,v), and its children or its patch. */
    private static final class Node {
        /** Corner locations (u,v) of a quad, or of a triangle in slots 0 to 5. */
        final double[] loc;
        /** Children (4, or one per corner below an n-gon), or null at a leaf. */
        Node[] kids;
        /** Per child of a quad, the box (u from, u to, v from, v to) that picks it. */
        double[] box;
        /** A leaf's patch: one of these, or none where the point is not evaluated. */
        FaceSurface patch;
        GregoryPatch gregory;
        GregoryTriangle triangle;
        /**
         * At the grid level, an irregular sub-face's corners' limit positions there (xyz each, by
         * the scheme's limit masks), which a point exactly at a corner takes.
         */
        double[] cornerLimit;
        /** A sub-face still to be refined: its level (as kept around it), its face there and its depth. */
        RefinedMesh mesh;
        int at, level;
        /** A leaf's map from (u,v) to its patch's (s,t): s = su (u - loc0) + sv (v - loc1), likewise t. */
        double su, sv, tu, tv;

        Node(double[] loc) { this.loc = loc; }

        /** The patch's parameter axes: from corner 0 to corner 1 (s) and to corner b (t). */
        void map(int b) {
            double ax = loc[2] - loc[0], ay = loc[3] - loc[1], bx = loc[2 * b] - loc[0], by = loc[2 * b + 1] - loc[1];
            double det = ax * by - bx * ay;
            su = by / det; sv = -bx / det; tu = -ay / det; tv = ax / det;
        }
    }

    private final Node root;
    private final int n, columns, smooth, depth, gridLevel;
    private final boolean loop;
    /** Whether the patches are those of the UV value mesh rather than of the positions. */
    private final boolean faceVarying;
    /** The options the patches are decided and built with. */
    private final SubdivOptions options;
    private final double[] ps = new double[3], pt = new double[3];
    private int patches;

    private AdaptiveFaceSurface(int n, boolean loop, boolean faceVarying, SubdivOptions options, int smooth, int depth, int gridLevel) {
        this.gridLevel = gridLevel;
        this.n = n;
        this.faceVarying = faceVarying;
        this.options = options;
        this.columns = FaceSurface.subFaceColumns(n);
        this.loop = loop;
        this.smooth = smooth;
        this.depth = depth;
        this.root = new Node(loop ? new double[] {0, 0, 1, 0, 0, 1, 0, 0} : new double[] {0, 0, 1, 0, 1, 1, 0, 1});
    }

    /**
     * The evaluator of a face of a control mesh (its one-ring, see {@link PatchRefiner#local}, is
     * enough: the descent needs nothing beyond it).
     *
     * @param mesh the control mesh
     * @param face a face of it
     * @param smooth the approximation level for smooth features: sub-faces irregular only by
     *               smooth features are end patches at this level
     * @param depth the approximation level for sharp features: the deepest level descended to
     */
    static AdaptiveFaceSurface of(ControlMesh mesh, int face, int smooth, int depth) {
        return create(mesh, face, smooth, depth, -1, false);
    }

    /**
     * As {@link #of(ControlMesh, int, int, int)}, with the points of the power-of-two grid of
     * level {@code gridLevel} (rate 2^gridLevel per edge, at most {@code smooth}; -1 for none) at
     * the limit positions of the limit masks at that level, as uniform refinement to that level
     * places its vertices: Far's end patches, and its masks at deeper levels, do not give the same
     * value at every vertex (valence-2 vertices, darts, some irregular boundaries).
     */
    static AdaptiveFaceSurface of(ControlMesh mesh, int face, int smooth, int depth, int gridLevel) {
        return create(mesh, face, smooth, depth, gridLevel, false);
    }

    /**
     * The evaluator of the UV limit surface of a face of a control mesh with UVs whose channel is
     * not linear (see {@link FaceVaryingSurface}, which handles linear channels itself). The
     * evaluated point's first two coordinates are the UV, the third is 0.
     */
    static AdaptiveFaceSurface ofFaceVarying(ControlMesh mesh, int face, int smooth, int depth) {
        if (mesh.uvChannel == null || mesh.uvChannel.linear()) throw new IllegalArgumentException("no UVs, or linear UVs");
        return create(mesh, face, smooth, depth, -1, true);
    }

    private static AdaptiveFaceSurface create(ControlMesh mesh, int face, int smooth, int depth, int gridLevel, boolean faceVarying) {
        boolean loop = mesh.options().scheme() == SubdivOptions.Scheme.LOOP;
        // The value mesh carries its own corners (pinned values): the boundary option is the
        // geometry's, and the value mesh's tags were made with EDGE_ONLY.
        SubdivOptions opt = faceVarying ? mesh.options().withBoundary(SubdivOptions.Boundary.EDGE_ONLY) : mesh.options();
        RefinedMesh r = RefinedMesh.base(mesh);
        FaceVarying.Channel uv = mesh.uvChannel;
        if (faceVarying && uv.linearBoundaries()) {
            // Far pins every new UV boundary value too, Bfr only the control mesh's: the values
            // are the same (each seam segment between pinned values stays a straight, evenly
            // split line), but unpinned the sub-faces along a seam become regular boundary patches.
            r = r.with(r.topo, r.positions(), new FaceVarying.Channel(uv.level(), uv.values(), false, false));
        }
        int n = r.topo.faceSize(face);
        AdaptiveFaceSurface a = new AdaptiveFaceSurface(n, loop, faceVarying, opt, smooth, depth, gridLevel);
        a.settle(a.root, r, a.points(r), face, 0, !loop && n != 4);
        return a;
    }

    /** The points the patches of a level are built from: its positions, or its UVs as (u, v, 0). */
    private double[] points(RefinedMesh r) {
        if (!faceVarying) return r.positions();
        double[] uv = r.uvChannel().values(), xyz = new double[uv.length / 2 * 3];
        for (int i = 0, m = uv.length / 2; i < m; i++) {
            xyz[3 * i] = uv[2 * i];
            xyz[3 * i + 1] = uv[2 * i + 1];
        }
        return xyz;
    }

    /**
     * Refines a sub-face left to be refined: its level (kept around it) once more, cut down to
     * its children's one-rings, and the children settled or left to be refined in turn.
     */
    private void expand(Node q) {
        RefinedMesh r = q.mesh, next = r.refine();
        Level p = r.topo, c = next.topo;
        int f = q.at, d = q.level, h0 = p.firstHalf(f);
        boolean ngonRoot = d == 0 && !loop && n != 4;
        int count = ngonRoot ? n : 4;
        Node[] kids = new Node[count];
        int[] at = new int[count];
        if (loop) {
            double[] loc = q.loc;
            double[] m01 = mid(loc, 0, 1), m12 = mid(loc, 1, 2), m20 = mid(loc, 2, 0);
            double[][] tri = {
                {loc[0], loc[1], m01[0], m01[1], m20[0], m20[1], 0, 0},
                {m01[0], m01[1], loc[2], loc[3], m12[0], m12[1], 0, 0},
                {m20[0], m20[1], m12[0], m12[1], loc[4], loc[5], 0, 0},
                {m12[0], m12[1], m20[0], m20[1], m01[0], m01[1], 0, 0}};
            for (int k = 0; k < 4; k++) {
                kids[k] = new Node(tri[k]);
                at[k] = 4 * f + k; // child j of face f is face 4f + j
            }
        } else if (ngonRoot) {
            // Bfr's sub-face k of an n-gon: the child face at corner k.
            for (int k = 0; k < n; k++) {
                double x = k % columns, y = k / columns;
                double[] cl = new double[8];
                placeChild(p, c, h0 + k, n, x, y, x + 0.5, y, x + 0.5, y + 0.5, x, y + 0.5, cl);
                kids[k] = new Node(cl);
                at[k] = h0 + k; // the child face of parent half-edge h is face h
            }
        } else {
            double[] loc = q.loc;
            double[] box = new double[16];
            for (int j = 0; j < 4; j++) {
                int jn = (j + 1) & 3, jp = (j + 3) & 3;
                double cx = loc[2 * j], cy = loc[2 * j + 1];
                double ex = (cx + loc[2 * jn]) / 2, ey = (cy + loc[2 * jn + 1]) / 2;
                double mx = (loc[0] + loc[2] + loc[4] + loc[6]) / 4, my = (loc[1] + loc[3] + loc[5] + loc[7]) / 4;
                double px = (cx + loc[2 * jp]) / 2, py = (cy + loc[2 * jp + 1]) / 2;
                box[4 * j] = Math.min(cx, mx);
                box[4 * j + 1] = Math.max(cx, mx);
                box[4 * j + 2] = Math.min(cy, my);
                box[4 * j + 3] = Math.max(cy, my);
                double[] cl = new double[8];
                placeChild(p, c, h0 + j, 4, cx, cy, ex, ey, mx, my, px, py, cl);
                kids[j] = new Node(cl);
                at[j] = h0 + j;
            }
            q.box = box;
        }
        // Only the children's one-rings are kept (their values, and their refinements', are exact).
        if (PatchRefiner.prunable(next)) {
            int[] faceAt = PatchRefiner.keptFaces(next, at, count);
            next = PatchRefiner.prune(next, faceAt);
            for (int k = 0; k < count; k++) at[k] = faceAt[at[k]];
        }
        double[] points = points(next);
        for (int k = 0; k < count; k++) settle(kids[k], next, points, at[k], d + 1, false);
        q.kids = kids;
        q.mesh = null;
    }

    /**
     * Settles a sub-face (face f of level r, at depth d) as a leaf with its regular patch or end
     * patch (or none: not evaluated), or leaves it, with its level, to be refined further.
     */
    private void settle(Node q, RefinedMesh r, double[] points, int f, int d, boolean ngonRoot) {
        Level l = faceVarying ? r.uvChannel().level() : r.topo;
        SubdivOptions opt = options;
        boolean regular = !ngonRoot && FaceSurface.isRegular(l, opt, f, true);
        // A regular patch's corners are its limit points already.
        if (d == gridLevel && !ngonRoot && !regular) q.cornerLimit = cornerLimits(r, f);
        if (regular) {
            q.patch = FaceSurface.patch(l, opt, points, f);
        } else if (d == depth || (d >= smooth && !ngonRoot && !sharpFeature(l, opt, f))) {
            if (d > 0) {
                if (loop) q.triangle = GregoryTriangle.of(l, opt, points, f);
                else q.gregory = GregoryPatch.of(l, opt, points, f);
            }
        } else {
            q.mesh = r;
            q.at = f;
            q.level = d;
            return;
        }
        q.map(loop ? 2 : 3);
        patches++;
    }

    /** The limit positions (by the limit masks) of face f's corners, xyz each. */
    private static double[] cornerLimits(RefinedMesh r, int f) {
        Level l = r.topo;
        int size = l.faceSize(f), h0 = l.firstHalf(f);
        boolean[] only = new boolean[l.nV];
        for (int c = 0; c < size; c++) only[l.hOrig[h0 + c]] = true;
        double[] all = new double[3 * l.nV], out = new double[3 * size];
        Limit.evaluate(l, SchemeRules.of(r.controlMesh().options()), r.positions(), all, null, only);
        for (int c = 0; c < size; c++) System.arraycopy(all, 3 * l.hOrig[h0 + c], out, 3 * c, 3);
        return out;
    }

    /** The number of patches (regular, end, or none) the face has been cut into so far. */
    int patchCount() { return patches; }

    /** Whether this class handles the face: a Catmull-Clark face with a limit surface. */
    static boolean supported(Level base, SubdivOptions options, int f) {
        return options.scheme() != SubdivOptions.Scheme.BILINEAR && !(base.hole != null && base.hole[f]);
    }

    /**
     * Whether a sub-face irregular at or below the smooth level is refined further (to the sharp
     * level), as Far's reduced feature set says: a semi-sharp vertex or edge at a corner, an
     * infinitely sharp corner vertex that is not a regular corner, or a non-manifold corner.
     * Smooth extraordinary vertices, inf-sharp darts and irregular inf-sharp creases are not.
     */
    static boolean sharpFeature(Level level, SubdivOptions options, int f) {
        int h0 = level.firstHalf(f);
        for (int c = 0; c < level.faceSize(f); c++) {
            int h = h0 + c, v = level.hOrig[h];
            if (level.isNonManifold(v)) return true;
            float vs = level.vertexSharpness(v);
            if (Crease.isSemiSharp(vs)) return true;
            int g = h;
            boolean open = false;
            while (true) {
                if (Crease.isSemiSharp(level.edgeSharpness(g))) return true;
                int gp = level.prev(g), t = level.hTwin[gp];
                if (Crease.isSemiSharp(level.edgeSharpness(gp))) return true;
                if (t < 0) { open = true; break; }
                if (t == h) break;
                g = t;
            }
            if (open) {
                g = h;
                while (true) {
                    int t = level.hTwin[g];
                    if (t < 0) break;
                    g = level.next(t);
                    if (Crease.isSemiSharp(level.edgeSharpness(g))) return true;
                }
            }
            boolean corner = Crease.isInfinite(vs) || FaceSurface.infSharpEdges(level, h) >= 3;
            if (corner && FaceSurface.corner(level, h, 0, true) != (1 << 1 | 1)) return true;
        }
        return false;
    }

    /**
     * The limit position and derivatives at (u,v) of the face's parameterization (Bfr's, see
     * {@link FaceSurface}); false, with the outputs untouched, where the point lies in a patch not
     * evaluated (an end patch with a corner not handled). Any output may be null; each takes 3
     * values. Allocates nothing once the sub-face the point falls in has been reached before (the
     * first time, the descent to it is made and kept).
     */
    boolean evaluate(double u, double v, double[] position, double[] du, double[] dv) {
        Node q = root, grid = null;
        int gridCorner = -1;
        while (true) {
            if (q.cornerLimit != null) {
                grid = q;
                gridCorner = corner(q.loc, u, v);
            }
            if (q.kids == null) {
                if (q.mesh == null) break;
                expand(q);
            }
            int k = -1;
            if (loop) {
                for (int j = 0; j < 4 && k < 0; j++) if (inside(q.kids[j].loc, u, v)) k = j;
            } else if (q == root && n != 4) {
                int ut = (int) u, vt = (int) v;
                if (u - ut > 0.75) ut++;
                if (v - vt > 0.75) vt++;
                k = columns * vt + ut;
                if (k >= n) k = -1;
            } else {
                double[] b = q.box;
                for (int j = 0; j < 4 && k < 0; j++) {
                    if (u >= b[4 * j] && u <= b[4 * j + 1] && v >= b[4 * j + 2] && v <= b[4 * j + 3]) k = j;
                }
            }
            if (k < 0) throw new IllegalArgumentException("(" + u + ", " + v + ") is outside the face");
            q = q.kids[k];
        }
        double ru = u - q.loc[0], rv = v - q.loc[1];
        double s = q.su * ru + q.sv * rv, t = q.tu * ru + q.tv * rv;
        if (q.patch != null) q.patch.evaluate(s, t, position, ps, pt);
        else if (q.gregory != null) q.gregory.evaluate(s, t, position, ps, pt);
        else if (q.triangle != null) q.triangle.evaluate(s, t, position, ps, pt);
        else return false;
        for (int i = 0; i < 3; i++) {
            if (du != null) du[i] = ps[i] * q.su + pt[i] * q.tu;
            if (dv != null) dv[i] = ps[i] * q.sv + pt[i] * q.tv;
        }
        if (gridCorner >= 0 && position != null) System.arraycopy(grid.cornerLimit, 3 * gridCorner, position, 0, 3);
        return true;
    }

    /** The corner of a sub-face (corner locations loc) that is exactly at (u,v), or -1. */
    private int corner(double[] loc, double u, double v) {
        for (int c = 0, size = loop ? 3 : 4; c < size; c++) if (loc[2 * c] == u && loc[2 * c + 1] == v) return c;
        return -1;
    }

    /**
     * The parametric locations of the corners of the child face of parent half-edge h (at the
     * parent's corner at (cx,cy); the edge it leaves, at (ex,ey); the face centre (mx,my); the
     * edge entering the corner, (px,py)), in the child's own corner order.
     */
    private static void placeChild(Level p, Level c, int h, int size, double cx, double cy, double ex, double ey,
            double mx, double my, double px, double py, double[] out) {
        int corner = p.hOrig[h], edgeOut = p.edge(h), edgeIn = p.edge(p.prev(h));
        int fc = h, c0 = c.firstHalf(fc);
        int pf = p.face(h);
        for (int j = 0; j < 4; j++) {
            int x = c.hOrig[c0 + j];
            double lx, ly;
            if (x < p.nV) {
                if (x != corner) throw new IllegalStateException("child face corner is not the parent corner");
                lx = cx; ly = cy;
            } else if (x < p.nV + p.nF) {
                if (x - p.nV != pf) throw new IllegalStateException("child face point of another face");
                lx = mx; ly = my;
            } else {
                int e = x - p.nV - p.nF;
                if (e == edgeOut && e != edgeIn) { lx = ex; ly = ey; }
                else if (e == edgeIn && e != edgeOut) { lx = px; ly = py; }
                else throw new IllegalStateException("ambiguous child edge point");
            }
            out[2 * j] = lx;
            out[2 * j + 1] = ly;
        }
    }

    private static double[] mid(double[] loc, int a, int b) {
        return new double[] {(loc[2 * a] + loc[2 * b]) / 2, (loc[2 * a + 1] + loc[2 * b + 1]) / 2};
    }

    private static boolean inside(double[] t, double u, double v) {
        double ax = t[2] - t[0], ay = t[3] - t[1], bx = t[4] - t[0], by = t[5] - t[1];
        double det = ax * by - bx * ay, ru = u - t[0], rv = v - t[1];
        double s = (by * ru - bx * rv) / det, w = (-ay * ru + ax * rv) / det;
        double eps = 1e-12;
        return s >= -eps && w >= -eps && s + w <= 1 + eps;
    }
}
