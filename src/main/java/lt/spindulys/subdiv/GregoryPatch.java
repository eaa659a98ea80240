package lt.spindulys.subdiv;

/**
 * The end patch OpenSubdiv puts on a Catmull-Clark quad still irregular at the deepest adaptive
 * level: a 20-point Gregory basis patch (Loop, Schaefer, Ni and Castaño, "Approximating
 * subdivision surfaces with Gregory patches for hardware tessellation", 2009, with Far's own
 * choice of limit points and tangents). Per corner: the corner point P (the limit position),
 * two edge points Ep and Em (P plus a third of the limit tangent along the face's two edges
 * at the corner, Far's tangent scaled by the subdivision matrix's eigenvalues), and two face
 * points Fp and Fm that make the cross-boundary derivatives of neighbouring patches agree;
 * regular corners get the B-spline patch's Bézier points. Evaluated as a bicubic Bézier patch
 * whose four interior points blend each corner's Fp and Fm rationally; derivatives, like Far's
 * default, are those of the Bézier patch with the blended interior points held fixed.
 *
 * <p>Corners as Far's end patches see them: a corner's fan ends at boundaries and infinitely sharp
 * edges (except at a dart, which keeps its whole ring); semi-sharp edges left at this level are
 * ignored; infinitely sharp vertices and vertices with three or more infinitely sharp edges are
 * sharp corners (P the vertex, edge points a third of the way to the next corners). {@link #of}
 * returns null for a non-quad or a non-manifold corner.
 */
final class GregoryPatch {
    /** Bézier points, 16 x xyz, row-major (t rows, s columns); interior ones for Fp and Fm separately. */
    private final double[] bez = new double[48], fm = new double[12];

    private GregoryPatch() {}

    /** The Gregory end patch of quad f of the level, or null if it has a corner not handled. */
    static GregoryPatch of(Level level, SubdivOptions options, double[] pos, int f) {
        if (level.faceSize(f) != 4) return null;
        int h0 = level.firstHalf(f);
        int[] corners = new int[4];
        for (int c = 0; c < 4; c++) corners[c] = level.hOrig[h0 + c];
        double[][] P = new double[4][], Ep = new double[4][], Em = new double[4][];
        int[][] rings = new int[4][];
        int[] faceInRing = new int[4], numFaces = new int[4];
        boolean[] boundary = new boolean[4], regular = new boolean[4], sharp = new boolean[4];
        double[] cos = new double[4];
        for (int c = 0; c < 4; c++) {
            int h = h0 + c, v = corners[c];
            if (level.isNonManifold(v)) return null;
            boolean cut = FaceSurface.endPatchCut(level, h);
            int ring = FaceSurface.corner(level, h, 0, cut);
            if (ring < 0) return null; // a sharp edge or a non-quad around the corner
            numFaces[c] = ring >> 1;
            boundary[c] = (ring & 1) != 0;
            float vs = level.vertexSharpness(v);
            sharp[c] = Crease.isInfinite(vs) || (boundary[c] && FaceSurface.infSharpEdges(level, h) >= 3)
                    || (boundary[c] && numFaces[c] == 1 && options.boundary() == SubdivOptions.Boundary.EDGE_AND_CORNER && FaceSurface.corner(level, h, 0, false) == 3);
            regular[c] = (numFaces[c] << (boundary[c] ? 1 : 0)) == 4 && !sharp[c];
            cos[c] = regular[c] ? 0 : Math.cos((boundary[c] ? Math.PI : 2 * Math.PI) / numFaces[c]);
            // The ring: edge i's far vertex at 2i, face i's opposite vertex at 2i + 1, faces
            // counter-clockwise from the first after a boundary (or from f inside).
            int g = h, fir = 0;
            if (boundary[c]) {
                while (FaceSurface.across(level, g, cut) >= 0) { g = level.next(level.hTwin[g]); fir++; }
            }
            int n = numFaces[c];
            int[] r = new int[2 * n + (boundary[c] ? 1 : 0)];
            for (int i = 0; i < n; i++) {
                r[2 * i] = level.dest(g);
                r[2 * i + 1] = level.hOrig[level.next(level.next(g))];
                if (i == n - 1 && boundary[c]) r[2 * n] = level.hOrig[level.prev(g)];
                int t = FaceSurface.across(level, level.prev(g), cut);
                if (t >= 0) g = t;
            }
            rings[c] = r;
            faceInRing[c] = fir;
        }
        for (int c = 0; c < 4; c++) {
            int next = corners[(c + 1) & 3], prev = corners[(c + 3) & 3], v = corners[c];
            int[] r = rings[c];
            P[c] = new double[3];
            Ep[c] = new double[3];
            Em[c] = new double[3];
            if (sharp[c]) {
                add(P[c], pos, v, 1);
                add(Ep[c], pos, v, 2.0 / 3); add(Ep[c], pos, next, 1.0 / 3);
                add(Em[c], pos, v, 2.0 / 3); add(Em[c], pos, prev, 1.0 / 3);
            } else if (boundary[c] && numFaces[c] == 1) {
                add(P[c], pos, v, 4.0 / 6); add(P[c], pos, next, 1.0 / 6); add(P[c], pos, prev, 1.0 / 6);
                add(Ep[c], pos, v, 2.0 / 3); add(Ep[c], pos, next, 1.0 / 3);
                add(Em[c], pos, v, 2.0 / 3); add(Em[c], pos, prev, 1.0 / 3);
            } else if (regular[c] && !boundary[c]) {
                add(P[c], pos, v, 4.0 / 9);
                for (int i = 0; i < 4; i++) { add(P[c], pos, r[2 * i], 1.0 / 9); add(P[c], pos, r[2 * i + 1], 1.0 / 36); }
                // Bézier edge points: along the edge to the next corner (ring edge 0) and to the previous (edge 1).
                add(Ep[c], pos, v, 4.0 / 9); add(Ep[c], pos, r[0], 2.0 / 9); add(Ep[c], pos, r[2], 1.0 / 9); add(Ep[c], pos, r[6], 1.0 / 9);
                add(Ep[c], pos, r[1], 1.0 / 18); add(Ep[c], pos, r[7], 1.0 / 18);
                add(Em[c], pos, v, 4.0 / 9); add(Em[c], pos, r[2], 2.0 / 9); add(Em[c], pos, r[0], 1.0 / 9); add(Em[c], pos, r[4], 1.0 / 9);
                add(Em[c], pos, r[1], 1.0 / 18); add(Em[c], pos, r[3], 1.0 / 18);
            } else if (regular[c]) {
                // Regular boundary corner: the boundary curve's Bézier points, the interior edge's.
                boolean epOnBoundary = faceInRing[c] == 0;
                add(P[c], pos, v, 2.0 / 3); add(P[c], pos, r[0], 1.0 / 6); add(P[c], pos, r[4], 1.0 / 6);
                double[] eb = epOnBoundary ? Ep[c] : Em[c], ei = epOnBoundary ? Em[c] : Ep[c];
                add(eb, pos, v, 2.0 / 3); add(eb, pos, r[epOnBoundary ? 0 : 4], 1.0 / 3);
                add(ei, pos, v, 4.0 / 9); add(ei, pos, r[2], 2.0 / 9); add(ei, pos, r[0], 1.0 / 9); add(ei, pos, r[4], 1.0 / 9);
                add(ei, pos, r[1], 1.0 / 18); add(ei, pos, r[3], 1.0 / 18);
            } else if (boundary[c]) {
                // Boundary extraordinary corner of k faces: the boundary curve's limit point, and
                // Far's interior tangent (a sine series over the ring) rotated onto each edge.
                int k = numFaces[c], last = 2 * k;
                double th = Math.PI / k, co = Math.cos(th), si = Math.sin(th);
                double div = 1.0 / (3 * k + co);
                double gamma = -4 * si * div, a0 = -((1 + 2 * co) * Math.sqrt(1 + co)) * div / Math.sqrt(1 - co), b0 = si * div;
                double[] tan = new double[3];
                add(tan, pos, v, gamma / 3); add(tan, pos, r[0], a0 / 3); add(tan, pos, r[1], b0 / 3); add(tan, pos, r[last], a0 / 3);
                for (int i = 1; i < k; i++) {
                    add(tan, pos, r[2 * i], 4 * Math.sin(th * i) * div / 3);
                    add(tan, pos, r[2 * i + 1], (Math.sin(th * i) + Math.sin(th * (i + 1))) * div / 3);
                }
                add(P[c], pos, v, 4.0 / 6); add(P[c], pos, r[0], 1.0 / 6); add(P[c], pos, r[last], 1.0 / 6);
                for (int e = 0; e < 2; e++) {
                    double[] out = e == 0 ? Ep[c] : Em[c];
                    boolean onBoundary = e == 0 ? faceInRing[c] == 0 : faceInRing[c] == k - 1;
                    if (onBoundary) {
                        add(out, pos, v, 2.0 / 3); add(out, pos, r[e == 0 ? 0 : last], 1.0 / 3);
                        continue;
                    }
                    double a = th * (faceInRing[c] + e), sa = Math.sin(a), ca = Math.cos(a);
                    for (int d = 0; d < 3; d++) out[d] = P[c][d] + sa * tan[d];
                    add(out, pos, r[0], ca / 6); add(out, pos, r[last], -ca / 6);
                }
            } else {
                // Interior extraordinary corner of valence n (ring starting at f: faceInRing 0).
                int n = numFaces[c];
                double pc = 1.0 / n / (n + 5);
                add(P[c], pos, v, n / (n + 5.0));
                for (int i = 0; i < n; i++) { add(P[c], pos, r[2 * i], 4 * pc); add(P[c], pos, r[2 * i + 1], pc); }
                // Far's tangent along ring edge k: the sum over faces i of cos(2 pi (i - k) / n)
                // times (2 e(i-1) + f(i-1) + 4 e(i) + f(i) + 2 e(i+1)), scaled by its eigenvalue factor.
                double tc = tangentScale(n) * 0.5 / (n + 5);
                for (int k = 0; k < 2; k++) {
                    double[] e = k == 0 ? Ep[c] : Em[c];
                    for (int d = 0; d < 3; d++) e[d] = P[c][d];
                    for (int i = 0; i < n; i++) {
                        double w = tc * Math.cos(2 * Math.PI * i / n);
                        int j = (i + k) % n, jp = (j + n - 1) % n, jn = (j + 1) % n;
                        add(e, pos, r[2 * jp], 2 * w); add(e, pos, r[2 * jp + 1], w);
                        add(e, pos, r[2 * j], 4 * w); add(e, pos, r[2 * j + 1], w);
                        add(e, pos, r[2 * jn], 2 * w);
                    }
                }
            }
        }
        // Face points.
        double[][] Fp = new double[4][], Fm = new double[4][];
        boolean[] fpReg = new boolean[4], fmReg = new boolean[4], fpCopy = new boolean[4], fmCopy = new boolean[4];
        for (int c = 0; c < 4; c++) {
            fpReg[c] = regular[c] && regular[(c + 1) & 3];
            fmReg[c] = regular[c] && regular[(c + 3) & 3];
            if (boundary[c]) {
                boolean epOn = faceInRing[c] == 0, emOn = faceInRing[c] == numFaces[c] - 1;
                if (numFaces[c] > 1) {
                    if (epOn) { fpReg[c] = fmReg[c]; fpCopy[c] = !fpReg[c]; }
                    if (emOn) { fmReg[c] = fpReg[c]; fmCopy[c] = !fmReg[c]; }
                } else {
                    fpReg[c] = fmReg[c] = true;
                }
            }
        }
        for (int c = 0; c < 4; c++) {
            int cn = (c + 1) & 3, co = (c + 2) & 3, cp = (c + 3) & 3;
            double[] reg = new double[3];
            add(reg, pos, corners[c], 4.0 / 9); add(reg, pos, corners[cp], 2.0 / 9); add(reg, pos, corners[cn], 2.0 / 9); add(reg, pos, corners[co], 1.0 / 9);
            int val = numFaces[c] + (boundary[c] ? 1 : 0);
            if (fpReg[c]) Fp[c] = reg;
            else if (!fpCopy[c]) Fp[c] = facePoint(pos, rings[c], val, faceInRing[c], cos[c], cos[cn], P[c], Ep[c], Em[cn], 1);
            if (fmReg[c]) Fm[c] = reg;
            else if (!fmCopy[c]) Fm[c] = facePoint(pos, rings[c], val, (faceInRing[c] + 1) % val, cos[c], cos[cp], P[c], Em[c], Ep[cp], -1);
            if (fpCopy[c]) Fp[c] = Fm[c];
            if (fmCopy[c]) Fm[c] = Fp[c];
        }
        GregoryPatch g = new GregoryPatch();
        // Boundary Bézier points: corners and edge points; interior: Fp in bez, Fm aside.
        g.put(0, 0, P[0]); g.put(1, 0, Ep[0]); g.put(2, 0, Em[1]); g.put(3, 0, P[1]);
        g.put(0, 1, Em[0]); g.put(3, 1, Ep[1]); g.put(0, 2, Ep[3]); g.put(3, 2, Em[2]);
        g.put(0, 3, P[3]); g.put(1, 3, Em[3]); g.put(2, 3, Ep[2]); g.put(3, 3, P[2]);
        g.put(1, 1, Fp[0]); g.put(2, 1, Fp[1]); g.put(2, 2, Fp[2]); g.put(1, 2, Fp[3]);
        for (int c = 0; c < 4; c++) System.arraycopy(Fm[c], 0, g.fm, 3 * c, 3);
        return g;
    }

    /** Far's eigenvalue factor for the limit tangents at an interior vertex of valence n. */
    static double tangentScale(int n) {
        double c = Math.cos(2 * Math.PI / n);
        return 16.0 / n / ((c + 5) + Math.sqrt((c + 9) * (c + 1)));
    }

    /**
     * A face point at a corner, beside ring edge {@code edge} (the edge to the adjacent corner
     * whose edge point is eFar): a combination of P and the two edge points by the corners'
     * angles, plus the difference of the ring points on either side of the edge (sign chooses
     * the side).
     */
    private static double[] facePoint(double[] pos, int[] r, int val, int edge, double cosNear, double cosFar,
            double[] p, double[] eNear, double[] eFar, double sign) {
        double[] out = new double[3];
        double a = cosFar / 3, b = (3 - 2 * cosNear - cosFar) / 3, c = 2 * cosNear / 3;
        for (int d = 0; d < 3; d++) out[d] = a * p[d] + b * eNear[d] + c * eFar[d];
        int prev = (edge + val - 1) % val, next = (edge + 1) % val;
        add(out, pos, r[2 * prev], -sign / 9);
        add(out, pos, r[2 * prev + 1], -sign / 18);
        add(out, pos, r[2 * edge + 1], sign / 18);
        add(out, pos, r[2 * next], sign / 9);
        return out;
    }

    private static void add(double[] acc, double[] pos, int v, double w) {
        acc[0] += w * pos[3 * v];
        acc[1] += w * pos[3 * v + 1];
        acc[2] += w * pos[3 * v + 2];
    }

    private void put(int col, int row, double[] p) {
        System.arraycopy(p, 0, bez, 3 * (4 * row + col), 3);
    }

    /**
     * Position and derivatives at (s,t) of the patch's own parameterization (corner 0 at (0,0),
     * corner 1 at (1,0)). Allocates nothing; any output may be null.
     */
    void evaluate(double s, double t, double[] position, double[] ds, double[] dt) {
        // Interior points (5, 6, 10, 9 for corners 0..3): G Fp + (1 - G) Fm, with G by the
        // distance to each corner's two edges; Far takes G as num * (1/den), and 1 - that for Fm.
        double g0 = weight(s, s + t), g1 = weight(t, 1 - s + t), g2 = weight(1 - s, 2 - s - t), g3 = weight(1 - t, s + 1 - t);
        double u = 1 - s, w = 1 - t;
        double bs0 = u * u * u, bs1 = 3 * s * u * u, bs2 = 3 * s * s * u, bs3 = s * s * s;
        double bt0 = w * w * w, bt1 = 3 * t * w * w, bt2 = 3 * t * t * w, bt3 = t * t * t;
        double ds0 = -3 * u * u, ds1 = 3 * u * u - 6 * s * u, ds2 = 6 * s * u - 3 * s * s, ds3 = 3 * s * s;
        double dt0 = -3 * w * w, dt1 = 3 * w * w - 6 * t * w, dt2 = 6 * t * w - 3 * t * t, dt3 = 3 * t * t;
        for (int d = 0; d < 3; d++) {
            double p = 0, ps = 0, pt = 0;
            for (int row = 0; row < 4; row++) {
                double br = row == 0 ? bt0 : row == 1 ? bt1 : row == 2 ? bt2 : bt3;
                double dr = row == 0 ? dt0 : row == 1 ? dt1 : row == 2 ? dt2 : dt3;
                for (int col = 0; col < 4; col++) {
                    int i = 4 * row + col;
                    double x = bez[3 * i + d];
                    if (i == 5) x = g0 * x + (1 - g0) * fm[d];
                    else if (i == 6) x = g1 * x + (1 - g1) * fm[3 + d];
                    else if (i == 10) x = g2 * x + (1 - g2) * fm[6 + d];
                    else if (i == 9) x = g3 * x + (1 - g3) * fm[9 + d];
                    double bc = col == 0 ? bs0 : col == 1 ? bs1 : col == 2 ? bs2 : bs3;
                    double dc = col == 0 ? ds0 : col == 1 ? ds1 : col == 2 ? ds2 : ds3;
                    p += bc * br * x;
                    ps += dc * br * x;
                    pt += bc * dr * x;
                }
            }
            if (position != null) position[d] = p;
            if (ds != null) ds[d] = ps;
            if (dt != null) dt[d] = pt;
        }
    }

    private static double weight(double num, double den) {
        return den <= 0 ? 1 : num * (1 / den);
    }
}
