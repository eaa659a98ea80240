package lt.spindulys.subdiv;

/**
 * The end patch OpenSubdiv puts on a Loop triangle still irregular at the
 * deepest adaptive level: an 18-point quartic Gregory triangle, a quartic Bézier triangle whose
 * three interior points each blend a pair of face points rationally. Per corner the limit
 * position P, two edge points Ep and Em (P plus a scaled limit tangent along each of the
 * triangle's edges at the corner, from Loop's limit masks) and two face points; per edge a
 * mid-edge point; the cubic edge points are raised to quartic ones. Regular corners take the
 * box spline's own Bézier points. Derivatives, like Far's, hold the blended interior points fixed.
 *
 * <p>Corners as in {@link GregoryPatch}; {@link #of} returns null for a non-triangle or a
 * non-manifold corner.
 */
final class GregoryTriangle {
    /** Quartic Bézier points (15 x xyz, index {@link #bi}); the three interior ones hold Fp, fm the Fm. */
    private final double[] bez = new double[45], fm = new double[9];

    private GregoryTriangle() {}

    /** Bézier index of the point with exponents i of u and j of v (degree 4). */
    private static int bi(int i, int j) {
        return ROW_START[j] + i;
    }

    private static final int[] ROW_START = {0, 5, 9, 12, 14};
    private static final int I11 = bi(1, 1), I21 = bi(2, 1), I12 = bi(1, 2);

    static GregoryTriangle of(Level level, SubdivOptions options, double[] pos, int f) {
        if (level.faceSize(f) != 3) return null;
        int h0 = level.firstHalf(f);
        int[] cv = new int[3];
        for (int c = 0; c < 3; c++) cv[c] = level.hOrig[h0 + c];
        int[][] rings = new int[3][];
        int[] fir = new int[3], nf = new int[3], val = new int[3];
        boolean[] bnd = new boolean[3], reg = new boolean[3], sharp = new boolean[3], epOn = new boolean[3], emOn = new boolean[3];
        double[] cos = new double[3];
        for (int c = 0; c < 3; c++) {
            int h = h0 + c, v = cv[c];
            if (level.isNonManifold(v)) return null;
            boolean cut = FaceSurface.endPatchCut(level, h);
            int ring = FaceSurface.corner(level, h, 0, cut);
            if (ring < 0) return null;
            nf[c] = ring >> 1;
            bnd[c] = (ring & 1) != 0;
            float vs = level.vertexSharpness(v);
            sharp[c] = Crease.isInfinite(vs) || (bnd[c] && FaceSurface.infSharpEdges(level, h) >= 3)
                    || (bnd[c] && nf[c] == 1 && options.boundary() == SubdivOptions.Boundary.EDGE_AND_CORNER && FaceSurface.corner(level, h, 0, false) == 3);
            reg[c] = (nf[c] << (bnd[c] ? 1 : 0)) == 6 && !sharp[c];
            cos[c] = reg[c] ? 0.5 : Math.cos((bnd[c] ? Math.PI : 2 * Math.PI) / nf[c]);
            val[c] = nf[c] + (bnd[c] ? 1 : 0);
            int g = h, k = 0;
            if (bnd[c]) while (FaceSurface.across(level, g, cut) >= 0) { g = level.next(level.hTwin[g]); k++; }
            int[] r = new int[val[c]];
            for (int i = 0; i < nf[c]; i++) {
                r[i] = level.dest(g);
                if (i == nf[c] - 1 && bnd[c]) r[nf[c]] = level.hOrig[level.prev(g)];
                int t = FaceSurface.across(level, level.prev(g), cut);
                if (t >= 0) g = t;
            }
            rings[c] = r;
            fir[c] = k;
            epOn[c] = bnd[c] && k == 0;
            emOn[c] = bnd[c] && k == nf[c] - 1;
        }
        double[][] P = new double[3][3], Ep = new double[3][3], Em = new double[3][3];
        for (int c = 0; c < 3; c++) {
            int v = cv[c], next = cv[(c + 1) % 3], prev = cv[(c + 2) % 3];
            int[] r = rings[c];
            if (sharp[c]) {
                add(P[c], pos, v, 1);
                add(Ep[c], pos, v, 2.0 / 3); add(Ep[c], pos, next, 1.0 / 3);
                add(Em[c], pos, v, 2.0 / 3); add(Em[c], pos, prev, 1.0 / 3);
            } else if (bnd[c] && nf[c] == 1) {
                add(P[c], pos, v, 4.0 / 6); add(P[c], pos, next, 1.0 / 6); add(P[c], pos, prev, 1.0 / 6);
                add(Ep[c], pos, v, 2.0 / 3); add(Ep[c], pos, next, 1.0 / 3);
                add(Em[c], pos, v, 2.0 / 3); add(Em[c], pos, prev, 1.0 / 3);
            } else if (reg[c] && !bnd[c]) {
                add(P[c], pos, v, 0.5);
                for (int i = 0; i < 6; i++) add(P[c], pos, r[i], 1.0 / 12);
                double[] ew = {7, 5, 1, -1, 1, 5};
                for (int k = 0; k < 2; k++) {
                    double[] e = k == 0 ? Ep[c] : Em[c];
                    add(e, pos, v, 0.5);
                    for (int i = 0; i < 6; i++) add(e, pos, r[(k + i) % 6], ew[i] / 36);
                }
            } else if (reg[c]) {
                add(P[c], pos, v, 2.0 / 3); add(P[c], pos, r[0], 1.0 / 6); add(P[c], pos, r[3], 1.0 / 6);
                for (int k = 0; k < 2; k++) {
                    double[] e = k == 0 ? Ep[c] : Em[c];
                    boolean on = k == 0 ? epOn[c] : emOn[c];
                    if (on) {
                        add(e, pos, v, 2.0 / 3); add(e, pos, r[k == 0 ? 0 : 3], 1.0 / 3);
                    } else {
                        boolean otherOn = k == 0 ? emOn[c] : epOn[c];
                        add(e, pos, v, 0.5); add(e, pos, r[1], 1.0 / 6); add(e, pos, r[2], 1.0 / 6);
                        add(e, pos, r[k == 0 ? (otherOn ? 3 : 0) : (otherOn ? 0 : 3)], 1.0 / 6);
                    }
                }
            } else if (bnd[c]) {
                // Boundary extraordinary corner: Loop's crease limit masks (Sdc's), the interior
                // tangent scaled by 1/24 and turned onto each edge with the boundary tangent.
                int k = nf[c], last = val[c] - 1;
                SchemeRules.LimitMasks m = new SchemeRules.LimitMasks(val[c]);
                float[] sh = new float[val[c]];
                sh[0] = sh[last] = Crease.INFINITE;
                LoopRules.RULES.limitMasks(Crease.RULE_CREASE, val[c], k, false, sh, m);
                add(P[c], pos, v, m.vw); add(P[c], pos, r[0], m.ew[0]); add(P[c], pos, r[last], m.ew[last]);
                double[] tan = new double[3];
                add(tan, pos, v, m.t2v);
                for (int i = 0; i < val[c]; i++) add(tan, pos, r[i], m.t2e[i]);
                for (int e = 0; e < 2; e++) {
                    double[] out = e == 0 ? Ep[c] : Em[c];
                    if (e == 0 && fir[c] == 0) {
                        add(out, pos, v, 2.0 / 3); add(out, pos, r[0], 1.0 / 3);
                        continue;
                    }
                    double a = Math.PI / k * ((fir[c] + e) % val[c]), sa = Math.sin(a), ca = Math.cos(a);
                    for (int d = 0; d < 3; d++) out[d] = P[c][d] + sa * tan[d] / 24;
                    add(out, pos, r[0], ca / 6); add(out, pos, r[last], -ca / 6);
                }
            } else {
                // Interior extraordinary corner: Loop's limit position mask, and the limit
                // tangent along each edge (cosines around the ring) scaled by
                // (3 + 2 cos(2 pi / n)) / (6 n), added to it.
                int n = nf[c];
                double ew = limitEdgeWeight(n);
                add(P[c], pos, v, 1 - ew * n);
                for (int i = 0; i < n; i++) add(P[c], pos, r[i], ew);
                double scale = (3 + 2 * Math.cos(2 * Math.PI / n)) / (6.0 * n);
                for (int k = 0; k < 2; k++) {
                    double[] e = k == 0 ? Ep[c] : Em[c];
                    for (int d = 0; d < 3; d++) e[d] = P[c][d];
                    for (int i = 0; i < n; i++) add(e, pos, r[(i + k) % n], scale * Math.cos(2 * Math.PI * i / n));
                }
            }
        }
        // Face points.
        boolean[] fpReg = new boolean[3], fmReg = new boolean[3], fpCopy = new boolean[3], fmCopy = new boolean[3];
        for (int c = 0; c < 3; c++) {
            fpReg[c] = reg[c] && reg[(c + 1) % 3];
            fmReg[c] = reg[c] && reg[(c + 2) % 3];
            if (bnd[c]) {
                if (nf[c] > 1) {
                    if (epOn[c]) { fpReg[c] = fmReg[c]; fpCopy[c] = !fpReg[c]; }
                    if (emOn[c]) { fmReg[c] = fpReg[c]; fmCopy[c] = !fmReg[c]; }
                } else {
                    fpReg[c] = fmReg[c] = true;
                }
            }
        }
        double[][] Fp = new double[3][], Fm = new double[3][];
        for (int c = 0; c < 3; c++) {
            int cn = (c + 1) % 3, cp = (c + 2) % 3;
            int[] r = rings[c];
            double[] rf = new double[3];
            if (!fpReg[c] && !fmReg[c]) {
                // no regular face point at this corner
            } else if (nf[c] == 1 && bnd[c]) {
                add(rf, pos, cv[c], 0.5); add(rf, pos, cv[cn], 0.25); add(rf, pos, cv[cp], 0.25);
            } else if (epOn[c]) {
                add(rf, pos, cv[c], 11.0 / 24); add(rf, pos, r[0], 7.0 / 24); add(rf, pos, r[1], 5.0 / 24); add(rf, pos, r[2], 1.0 / 24);
            } else if (emOn[c]) {
                add(rf, pos, cv[c], 11.0 / 24); add(rf, pos, r[3], 7.0 / 24); add(rf, pos, r[2], 5.0 / 24); add(rf, pos, r[1], 1.0 / 24);
            } else {
                int eNext = bnd[c] ? 0 : (fir[c] + 5) % 6, ePrev = bnd[c] ? 3 : (fir[c] + 2) % 6;
                if (reg[c]) {
                    add(rf, pos, cv[c], 10.0 / 24); add(rf, pos, cv[cp], 0.25); add(rf, pos, cv[cn], 0.25);
                    add(rf, pos, r[ePrev], 1.0 / 24); add(rf, pos, r[eNext], 1.0 / 24);
                }
            }
            if (fpReg[c]) Fp[c] = rf;
            else if (!fpCopy[c]) Fp[c] = facePoint(pos, r, val[c], fir[c], cos[c], cos[cn], P[c], Ep[c], Em[cn], 1);
            if (fmReg[c]) Fm[c] = rf;
            else if (!fmCopy[c]) Fm[c] = facePoint(pos, r, val[c], (fir[c] + 1) % val[c], cos[c], cos[cp], P[c], Em[c], Ep[cp], -1);
            if (fpCopy[c]) Fp[c] = Fm[c];
            if (fmCopy[c]) Fm[c] = Fp[c];
        }
        // Mid-edge points (from the cubic edge points).
        double[][] M = new double[3][3];
        for (int e = 0; e < 3; e++) {
            int c0 = e, c1 = (e + 1) % 3;
            boolean boundaryEdge = epOn[c0] && emOn[c1], dartEdge = epOn[c0] != emOn[c1];
            if (boundaryEdge || (reg[c0] && reg[c1] && !dartEdge)) {
                if (epOn[c0]) {
                    add(M[e], pos, cv[c0], 0.5); add(M[e], pos, cv[c1], 0.5);
                } else {
                    int opp = bnd[c0] ? fir[c0] - 1 : (fir[c0] + 5) % 6;
                    add(M[e], pos, cv[c0], 1.0 / 3); add(M[e], pos, cv[c1], 1.0 / 3);
                    add(M[e], pos, cv[(e + 2) % 3], 1.0 / 6); add(M[e], pos, rings[c0][opp], 1.0 / 6);
                }
            } else {
                for (int d = 0; d < 3; d++) M[e][d] = 0.5 * Ep[c0][d] + 0.5 * Em[c1][d];
            }
        }
        // Cubic edge points raised to quartic ones: regular ones by their own quartic weights.
        double[][] Qp = new double[3][], Qm = new double[3][];
        for (int c = 0; c < 3; c++) {
            int[] r = rings[c];
            int v = cv[c], next = cv[(c + 1) % 3], prev = cv[(c + 2) % 3];
            for (int k = 0; k < 2; k++) {
                boolean on = k == 0 ? epOn[c] : emOn[c];
                double[] q = new double[3], e = k == 0 ? Ep[c] : Em[c];
                if (on && !sharp[c]) {
                    int x, y;
                    if (nf[c] == 1) { x = k == 0 ? next : prev; y = k == 0 ? prev : next; }
                    else { x = r[k == 0 ? 0 : val[c] - 1]; y = r[k == 0 ? val[c] - 1 : 0]; }
                    add(q, pos, v, 16.0 / 24); add(q, pos, x, 7.0 / 24); add(q, pos, y, 1.0 / 24);
                } else if (reg[c] && bnd[c]) {
                    boolean otherOn = k == 0 ? emOn[c] : epOn[c];
                    int x = k == 0 ? (otherOn ? 3 : 0) : (otherOn ? 0 : 3);
                    add(q, pos, v, 13.0 / 24); add(q, pos, r[1], 3.0 / 24); add(q, pos, r[2], 3.0 / 24);
                    add(q, pos, r[x], 4.0 / 24); add(q, pos, r[3 - x], 1.0 / 24);
                } else if (reg[c]) {
                    double[] w = {12, 4, 3, 1, 0, 1, 3};
                    add(q, pos, v, w[0] / 24);
                    for (int i = 0; i < 6; i++) add(q, pos, r[(k + i) % 6], w[i + 1] / 24);
                } else {
                    for (int d = 0; d < 3; d++) q[d] = 0.25 * P[c][d] + 0.75 * e[d];
                }
                if (k == 0) Qp[c] = q; else Qm[c] = q;
            }
        }
        GregoryTriangle g = new GregoryTriangle();
        g.put(0, 0, P[0]); g.put(1, 0, Qp[0]); g.put(0, 1, Qm[0]);
        g.put(4, 0, P[1]); g.put(3, 1, Qp[1]); g.put(3, 0, Qm[1]);
        g.put(0, 4, P[2]); g.put(0, 3, Qp[2]); g.put(1, 3, Qm[2]);
        g.put(2, 0, M[0]); g.put(2, 2, M[1]); g.put(0, 2, M[2]);
        g.put(1, 1, Fp[0]); g.put(2, 1, Fp[1]); g.put(1, 2, Fp[2]);
        for (int c = 0; c < 3; c++) System.arraycopy(Fm[c], 0, g.fm, 3 * c, 3);
        return g;
    }

    /** Loop's limit position weight of each neighbour of a smooth interior vertex of valence n. */
    private static double limitEdgeWeight(int n) {
        if (n == 6) return 1.0 / 12.0;
        double cosTheta = Math.cos(Math.PI * 2.0 / n);
        double beta = 0.25 * cosTheta + 0.375;
        double gamma = (0.625 - beta * beta) / n;
        return 1.0 / (n + 3.0 / (8.0 * gamma));
    }

    private static double[] facePoint(double[] pos, int[] r, int val, int edge, double cosNear, double cosFar,
            double[] p, double[] eNear, double[] eFar, double sign) {
        double[] out = new double[3];
        double a = cosFar / 4, b = (4 - 2 * cosNear - cosFar) / 4, c = 2 * cosNear / 4;
        for (int d = 0; d < 3; d++) out[d] = a * p[d] + b * eNear[d] + c * eFar[d];
        int prev = (edge + val - 1) % val, next = (edge + 1) % val;
        double rs = 0.25 * (7.0 / 18.0);
        add(out, pos, r[prev], -sign * rs);
        add(out, pos, r[next], sign * rs);
        return out;
    }

    private static void add(double[] acc, double[] pos, int v, double w) {
        acc[0] += w * pos[3 * v];
        acc[1] += w * pos[3 * v + 1];
        acc[2] += w * pos[3 * v + 2];
    }

    private void put(int i, int j, double[] p) {
        System.arraycopy(p, 0, bez, 3 * bi(i, j), 3);
    }

    /** Position and derivatives at (s,t), corner 1 at (1,0), corner 2 at (0,1). Allocates nothing; any output may be null. */
    void evaluate(double s, double t, double[] position, double[] ds, double[] dt) {
        double u = s, v = t, w = 1 - u - v;
        double gp0 = u + v > 0 ? u / (u + v) : 1, gp1 = v + w > 0 ? v / (v + w) : 1, gp2 = w + u > 0 ? w / (w + u) : 1;
        double gm0 = u + v > 0 ? v / (u + v) : 0, gm1 = v + w > 0 ? w / (v + w) : 0, gm2 = w + u > 0 ? u / (w + u) : 0;
        double px = 0, py = 0, pz = 0, ux = 0, uy = 0, uz = 0, vx = 0, vy = 0, vz = 0;
        for (int j = 0; j <= 4; j++) {
            for (int i = 0; i + j <= 4; i++) {
                int k = 4 - i - j;
                double coef = 24.0 / (fact(i) * fact(j) * fact(k));
                double B = coef * pw(u, i) * pw(v, j) * pw(w, k);
                double dBu = coef * ((i > 0 ? i * pw(u, i - 1) * pw(v, j) * pw(w, k) : 0) - (k > 0 ? k * pw(u, i) * pw(v, j) * pw(w, k - 1) : 0));
                double dBv = coef * ((j > 0 ? j * pw(u, i) * pw(v, j - 1) * pw(w, k) : 0) - (k > 0 ? k * pw(u, i) * pw(v, j) * pw(w, k - 1) : 0));
                int y = bi(i, j), x = 3 * y;
                double bx = bez[x], by = bez[x + 1], bz = bez[x + 2];
                // The interior points blend Fp and Fm.
                if (y == I11) { bx = gp0 * bx + gm0 * fm[0]; by = gp0 * by + gm0 * fm[1]; bz = gp0 * bz + gm0 * fm[2]; }
                else if (y == I21) { bx = gp1 * bx + gm1 * fm[3]; by = gp1 * by + gm1 * fm[4]; bz = gp1 * bz + gm1 * fm[5]; }
                else if (y == I12) { bx = gp2 * bx + gm2 * fm[6]; by = gp2 * by + gm2 * fm[7]; bz = gp2 * bz + gm2 * fm[8]; }
                px += B * bx; py += B * by; pz += B * bz;
                ux += dBu * bx; uy += dBu * by; uz += dBu * bz;
                vx += dBv * bx; vy += dBv * by; vz += dBv * bz;
            }
        }
        if (position != null) { position[0] = px; position[1] = py; position[2] = pz; }
        if (ds != null) { ds[0] = ux; ds[1] = uy; ds[2] = uz; }
        if (dt != null) { dt[0] = vx; dt[1] = vy; dt[2] = vz; }
    }

    private static double fact(int n) { return n <= 1 ? 1 : n == 2 ? 2 : n == 3 ? 6 : 24; }

    private static double pw(double x, int e) {
        double r = 1;
        for (int i = 0; i < e; i++) r *= x;
        return r;
    }
}
