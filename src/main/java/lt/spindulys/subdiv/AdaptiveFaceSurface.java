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
 * <p>The levels are given whole: the face's one-ring (see {@link PatchRefiner#local}) refined
 * uniformly to the sharp level, whose descendants of the face are exact. That is the simple,
 * costly form (about 9 x 4^6 faces per face); refining only the sub-faces descended into is the
 * next step for speed, not for values.
 */
final class AdaptiveFaceSurface {
    private final RefinedMesh[] levels;
    private final int face, smooth, depth, n, columns;

    /**
     * @param levels the mesh refined uniformly: levels[0] the base, at least {@code depth + 1} of them
     * @param face a face of the base level
     * @param smooth the approximation level for smooth features: sub-faces irregular only by
     *               smooth features are end patches at this level
     * @param depth the approximation level for sharp features: the deepest level descended to
     */
    AdaptiveFaceSurface(RefinedMesh[] levels, int face, int smooth, int depth) {
        if (levels.length <= depth) throw new IllegalArgumentException("need " + (depth + 1) + " levels");
        this.levels = levels;
        this.face = face;
        this.smooth = smooth;
        this.depth = depth;
        this.n = levels[0].topo.faceSize(face);
        this.columns = FaceSurface.subFaceColumns(n);
    }

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
     * {@link FaceSurface}); false, with the outputs untouched, where the point lies in an end
     * patch (not evaluated yet).
     */
    boolean evaluate(double u, double v, double[] position, double[] du, double[] dv) {
        // Parametric locations (in the face's (u,v)) of the current sub-face's corners.
        double[] loc = new double[8];
        int f = face, d = 0;
        Level base = levels[0].topo;
        SubdivOptions opt = levels[0].controlMesh().options();
        if (opt.scheme() == SubdivOptions.Scheme.LOOP) return evaluateTriangle(u, v, position, du, dv);
        if (n == 4) {
            double[] q = {0, 0, 1, 0, 1, 1, 0, 1};
            System.arraycopy(q, 0, loc, 0, 8);
            if (FaceSurface.isRegular(base, opt, f, true)) return evalPatch(0, f, loc, u, v, position, du, dv);
        }
        while (true) {
            if (d == depth || (d >= smooth && !(d == 0 && n != 4) && !sharpFeature(levels[d].topo, opt, f))) {
                return endPatch(d, f, loc, u, v, position, du, dv);
            }
            Level p = levels[d].topo, c = levels[d + 1].topo;
            int k, h0 = p.firstHalf(f);
            double[] cl = new double[8];
            if (d == 0 && n != 4) {
                // Bfr's sub-face q of an n-gon: the child face at corner q.
                int ut = (int) u, vt = (int) v;
                if (u - ut > 0.75) ut++;
                if (v - vt > 0.75) vt++;
                k = columns * vt + ut;
                if (k < 0 || k >= n) throw new IllegalArgumentException("(" + u + ", " + v + ") is outside the face");
                double x = ut, y = vt;
                placeChild(p, c, h0 + k, n, x, y, x + 0.5, y, x + 0.5, y + 0.5, x, y + 0.5, cl);
            } else {
                k = -1;
                for (int j = 0; j < 4 && k < 0; j++) {
                    int jn = (j + 1) & 3, jp = (j + 3) & 3;
                    double cx = loc[2 * j], cy = loc[2 * j + 1];
                    double ex = (cx + loc[2 * jn]) / 2, ey = (cy + loc[2 * jn + 1]) / 2;
                    double mx = (loc[0] + loc[2] + loc[4] + loc[6]) / 4, my = (loc[1] + loc[3] + loc[5] + loc[7]) / 4;
                    double px = (cx + loc[2 * jp]) / 2, py = (cy + loc[2 * jp + 1]) / 2;
                    double lo = Math.min(cx, mx), hi = Math.max(cx, mx), lo2 = Math.min(cy, my), hi2 = Math.max(cy, my);
                    if (u >= lo && u <= hi && v >= lo2 && v <= hi2) {
                        k = j;
                        placeChild(p, c, h0 + j, 4, cx, cy, ex, ey, mx, my, px, py, cl);
                    }
                }
                if (k < 0) throw new IllegalArgumentException("(" + u + ", " + v + ") is outside the face");
            }
            f = h0 + k; // the child face of parent half-edge h is face h
            loc = cl;
            d++;
            if (FaceSurface.isRegular(c, opt, f, true)) return evalPatch(d, f, loc, u, v, position, du, dv);
        }
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

    /** Loop: the descent through the four child triangles of each triangle. */
    private boolean evaluateTriangle(double u, double v, double[] position, double[] du, double[] dv) {
        SubdivOptions opt = levels[0].controlMesh().options();
        // Corner locations (u,v) of the current triangle; its corner 3 slot unused.
        double[] loc = {0, 0, 1, 0, 0, 1, 0, 0};
        int f = face;
        for (int d = 0; ; d++) {
            Level l = levels[d].topo;
            if (FaceSurface.isRegular(l, opt, f, true)) return evalPatch(d, f, tri(loc), u, v, position, du, dv);
            if (d == depth || (d >= smooth && !sharpFeature(l, opt, f))) return triangleEndPatch(d, f, loc, u, v, position, du, dv);
            double[] m01 = mid(loc, 0, 1), m12 = mid(loc, 1, 2), m20 = mid(loc, 2, 0);
            double[][] kids = {
                {loc[0], loc[1], m01[0], m01[1], m20[0], m20[1]},
                {m01[0], m01[1], loc[2], loc[3], m12[0], m12[1]},
                {m20[0], m20[1], m12[0], m12[1], loc[4], loc[5]},
                {m12[0], m12[1], m20[0], m20[1], m01[0], m01[1]}};
            int k = -1;
            for (int j = 0; j < 4 && k < 0; j++) if (inside(kids[j], u, v)) k = j;
            if (k < 0) throw new IllegalArgumentException("(" + u + ", " + v + ") is outside the face");
            loc = new double[] {kids[k][0], kids[k][1], kids[k][2], kids[k][3], kids[k][4], kids[k][5], 0, 0};
            f = 4 * f + k; // child j of face f is face 4f + j
        }
    }

    /** Far's end patch on a Loop sub-triangle (a quartic Gregory triangle), where handled. */
    private boolean triangleEndPatch(int d, int f, double[] loc, double u, double v, double[] position, double[] du, double[] dv) {
        if (d == 0) return false;
        RefinedMesh m = levels[d];
        GregoryTriangle g = GregoryTriangle.of(m.topo, m.controlMesh().options(), m.positions(), f);
        if (g == null) return false;
        double ax = loc[2] - loc[0], ay = loc[3] - loc[1], bx = loc[4] - loc[0], by = loc[5] - loc[1];
        double det = ax * by - bx * ay;
        double su = by / det, sv = -bx / det, tu = -ay / det, tv = ax / det;
        double ru = u - loc[0], rv = v - loc[1];
        double[] ps = new double[3], pt = new double[3];
        g.evaluate(su * ru + sv * rv, tu * ru + tv * rv, position, ps, pt);
        for (int i = 0; i < 3; i++) {
            if (du != null) du[i] = ps[i] * su + pt[i] * tu;
            if (dv != null) dv[i] = ps[i] * sv + pt[i] * tv;
        }
        return true;
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

    /** A triangle's corner locations laid out as {@link #evalPatch} reads them (t axis at slots 6, 7). */
    private static double[] tri(double[] loc) {
        return new double[] {loc[0], loc[1], loc[2], loc[3], 0, 0, loc[4], loc[5]};
    }

    /** Far's end patch (a Gregory basis patch) on sub-face f of level d, where handled. */
    private boolean endPatch(int d, int f, double[] loc, double u, double v, double[] position, double[] du, double[] dv) {
        if (d == 0) return false;
        RefinedMesh m = levels[d];
        GregoryPatch g = GregoryPatch.of(m.topo, m.controlMesh().options(), m.positions(), f);
        if (g == null) return false;
        double ax = loc[2] - loc[0], ay = loc[3] - loc[1], bx = loc[6] - loc[0], by = loc[7] - loc[1];
        double det = ax * by - bx * ay;
        double su = by / det, sv = -bx / det, tu = -ay / det, tv = ax / det;
        double ru = u - loc[0], rv = v - loc[1];
        double[] ps = new double[3], pt = new double[3];
        g.evaluate(su * ru + sv * rv, tu * ru + tv * rv, position, ps, pt);
        for (int i = 0; i < 3; i++) {
            if (du != null) du[i] = ps[i] * su + pt[i] * tu;
            if (dv != null) dv[i] = ps[i] * sv + pt[i] * tv;
        }
        return true;
    }

    private boolean evalPatch(int d, int f, double[] loc, double u, double v, double[] position, double[] du, double[] dv) {
        RefinedMesh m = levels[d];
        FaceSurface s = FaceSurface.patch(m.topo, m.controlMesh().options(), m.positions(), f);
        // (u,v) = L0 + s (L1 - L0) + t (L3 - L0)
        double ax = loc[2] - loc[0], ay = loc[3] - loc[1], bx = loc[6] - loc[0], by = loc[7] - loc[1];
        double det = ax * by - bx * ay;
        double su = by / det, sv = -bx / det, tu = -ay / det, tv = ax / det;
        double ru = u - loc[0], rv = v - loc[1];
        double s0 = su * ru + sv * rv, t0 = tu * ru + tv * rv;
        double[] ps = new double[3], pt = new double[3];
        s.evaluate(s0, t0, position, ps, pt);
        for (int i = 0; i < 3; i++) {
            if (du != null) du[i] = ps[i] * su + pt[i] * tu;
            if (dv != null) dv[i] = ps[i] * sv + pt[i] * tv;
        }
        return true;
    }
}
