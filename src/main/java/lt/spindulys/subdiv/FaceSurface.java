package lt.spindulys.subdiv;

/**
 * The limit surface of one face of a level, evaluated directly at the face's parameters (as
 * OpenSubdiv's {@code Bfr::Surface} does) instead of by refining: position and first derivatives
 * at any (u,v), without allocating.
 *
 * <p><b>Parameterization</b> (Bfr's): a quad of Catmull-Clark or bilinear has (u,v) in [0,1]^2,
 * corner 0 at (0,0), corner 1 at (1,0), corner 2 at (1,1); a Loop triangle has corner 1 at
 * (1,0), corner 2 at (0,1) and u + v &le; 1. Any other face of N corners is split into N quad
 * sub-faces, sub-face q (at corner q) covering [q % w, q % w + 1/2] x [q / w, q / w + 1/2] with
 * w = {@link #subFaceColumns}; its local coordinates, twice the offsets into that square, run
 * from corner q (0,0) along the edge leaving it to the face centre (1,1). Derivatives are with
 * respect to the face's (u,v).
 *
 * <p><b>What is exact here.</b>
 * <ul>
 * <li>Regular faces ({@link #isRegular}): a Catmull-Clark quad whose corners are all interior
 * of valence 4, or boundary of 2 faces, or sharp corners of one face, with no sharp edges and
 * no semi-sharp vertices around it and only quads in its neighbourhood, is the uniform bicubic
 * B-spline patch of its 16 neighbouring points; a missing row or column on a boundary stands for
 * the phantom points that extend the boundary linearly (2 B - I), folded into the weights. A
 * Loop triangle with the same conditions (valence 6 inside, 3 faces on a boundary) is the quartic
 * three-direction box-spline patch of its 12 neighbouring points, phantom points again
 * extrapolated across boundary edges and at boundary vertices, as OpenSubdiv does.</li>
 * <li>Bilinear faces: quads bilinearly; other faces per sub-face, the bilinear patch of the
 * corner, the two edge midpoints beside it and the face's centroid.</li>
 * </ul>
 * Irregular faces (extraordinary vertices, creases, n-gons of the smooth schemes) need local
 * adaptive refinement: {@link AdaptiveFaceSurface} descends to this class's regular patches
 * ({@link #patch}) and, at its deepest level, to Far's Gregory end patches.
 */
final class FaceSurface {
    private static final int BSPLINE = 0, BOX_SPLINE = 1, BILINEAR = 2, LINEAR_SUBFACES = 3;

    private final int kind;
    /** Control points, xyz each: 16 (B-spline), 12 (box spline), 4 (bilinear) or the N corners. */
    private final double[] cp;
    /** B-spline: bit k set when the face's edge k is on a boundary (row or column of phantoms). */
    private final int boundary;
    /** Sub-faces: the face size and the columns of the sub-face layout. */
    private final int n, columns;

    /** Box spline: its power-basis coefficients, xyz per monomial s^EX[k] t^EY[k]. */
    private final double[] poly;

    private FaceSurface(int kind, double[] cp, int boundary, int n) {
        this.kind = kind;
        this.cp = cp;
        this.boundary = boundary;
        this.n = n;
        this.columns = subFaceColumns(n);
        this.poly = kind == BOX_SPLINE ? powerBasis(cp) : null;
    }

    /** The box spline's polynomial: per monomial k, the sum over points i of BOX[i][k] / 12 times point i. */
    private static double[] powerBasis(double[] cp) {
        double[] a = new double[45];
        for (int k = 0; k < 15; k++) {
            for (int i = 0; i < 12; i++) {
                int c = BOX[i][k];
                if (c == 0) continue;
                for (int d = 0; d < 3; d++) a[3 * k + d] += c * cp[3 * i + d];
            }
            for (int d = 0; d < 3; d++) a[3 * k + d] /= 12;
        }
        return a;
    }

    /** Columns of Bfr's layout of an N-gon's quad sub-faces. */
    static int subFaceColumns(int n) {
        return n < 10 ? (n > 4 ? 3 : 2) : 1 + (int) Math.sqrt((float) (n - 1));
    }

    /**
     * The limit surface of face f of the control mesh, if this class can evaluate it exactly:
     * bilinear faces and regular faces ({@link #isRegular}).
     *
     * @throws UnsupportedOperationException for an irregular face of Catmull-Clark or Loop
     * @throws IllegalArgumentException for a hole
     */
    static FaceSurface of(ControlMesh mesh, int f) {
        return of(mesh.base, mesh.options(), mesh.positions(), f);
    }

    /** As {@link #of(ControlMesh, int)}, for face f of a level with the given vertex positions. */
    static FaceSurface of(Level level, SubdivOptions options, double[] positions, int f) {
        if (level.hole != null && level.hole[f]) throw new IllegalArgumentException("face " + f + " is a hole: it has no limit surface");
        if (options.scheme() == SubdivOptions.Scheme.BILINEAR) return linear(level, positions, f);
        if (!isRegular(level, options, f)) throw new UnsupportedOperationException("face " + f + " is irregular");
        return options.scheme() == SubdivOptions.Scheme.LOOP ? boxSpline(level, positions, f, false) : bSpline(level, positions, f, false);
    }

    /**
     * The regular patch of face f of a refined level where infinitely sharp edges count as
     * boundaries (OpenSubdiv's inf-sharp patches: each side of such a crease is the boundary
     * patch of its side), for the sub-faces of adaptive refinement.
     *
     * @throws UnsupportedOperationException unless {@link #isRegular(Level, SubdivOptions, int, boolean) isRegular(level, options, f, true)}
     */
    static FaceSurface patch(Level level, SubdivOptions options, double[] positions, int f) {
        if (options.scheme() == SubdivOptions.Scheme.BILINEAR) throw new UnsupportedOperationException("bilinear faces are linear");
        if (!isRegular(level, options, f, true)) throw new UnsupportedOperationException("face " + f + " is irregular");
        return options.scheme() == SubdivOptions.Scheme.LOOP ? boxSpline(level, positions, f, true) : bSpline(level, positions, f, true);
    }

    // ------------------------------------------------------------------ regularity

    /** The twin of half-edge h, or -1 on a boundary and, if {@code cut}, across an infinitely sharp edge. */
    static int across(Level level, int h, boolean cut) {
        int t = level.hTwin[h];
        if (t >= 0 && cut && Crease.isInfinite(level.edgeSharpness(h))) return -1;
        return t;
    }

    /**
     * Whether face f has a single regular patch as its limit surface (Bfr's {@code IsRegular}):
     * the scheme's regular face size, only such faces around its corners, no sharp edges at its
     * corners other than boundary edges, no semi-sharp or interior infinitely sharp vertices; each
     * corner (at a non-manifold vertex: its fan of faces holding f) interior of the regular valence (4, or 6 for Loop), a
     * smooth boundary vertex of half that many faces, or a sharp corner (infinitely sharp, or
     * made sharp by the boundary option) of a single face.
     */
    static boolean isRegular(Level level, SubdivOptions options, int f) {
        return isRegular(level, options, f, false);
    }

    /**
     * As {@link #isRegular(Level, SubdivOptions, int)}, or if {@code cut} with infinitely sharp
     * edges as boundaries (each corner's fan ends at them; a vertex with three or more of them
     * is a sharp corner).
     */
    static boolean isRegular(Level level, SubdivOptions options, int f, boolean cut) {
        if (options.scheme() == SubdivOptions.Scheme.BILINEAR) return false;
        int reg = options.scheme() == SubdivOptions.Scheme.LOOP ? 3 : 4;
        int interior = reg == 4 ? 4 : 6;
        if (level.faceSize(f) != reg) return false;
        int h0 = level.firstHalf(f);
        for (int c = 0; c < reg; c++) {
            int h = h0 + c, v = level.hOrig[h];
            float vs = level.vertexSharpness(v);
            if (Crease.isSemiSharp(vs)) return false;
            int ring = corner(level, h, reg, cut);
            if (ring < 0) return false;
            int faces = ring >> 1;
            if ((ring & 1) == 0) {
                if (Crease.isInfinite(vs) || faces != interior) return false;
            } else {
                boolean sharp = Crease.isInfinite(vs)
                        || (options.boundary() == SubdivOptions.Boundary.EDGE_AND_CORNER && faces == 1 && corner(level, h, 0, false) == (1 << 1 | 1))
                        || (cut && infSharpEdges(level, h) >= 3);
                if (faces != (sharp ? 1 : interior / 2)) return false;
            }
        }
        return true;
    }

    /**
     * The manifold fan of faces around the origin of half-edge h that holds h's face (all of a
     * manifold vertex's faces; at a non-manifold vertex, as in Bfr, the faces reached without
     * crossing a non-manifold edge): twice the number of faces, plus 1 if the fan is open (a
     * boundary). -1 if a face of another size than {@code reg} or a sharp edge (other than the
     * fan's ends) is in it.
     */
    static int corner(Level level, int h, int reg) {
        return corner(level, h, reg, false);
    }

    /**
     * Whether the fan of an end patch's corner at the origin of h ends at infinitely sharp edges
     * (the {@code cut} of {@link #corner(Level, int, int, boolean)}), as Far's end patches (Gregory
     * quad and triangle) take it: it does, except at a dart (one such edge ending inside the
     * mesh), which keeps its whole ring. Semi-sharp edges left at this level are ignored.
     */
    static boolean endPatchCut(Level level, int h) {
        return !(infSharpEdges(level, h) == 1 && (corner(level, h, 0, false) & 1) == 0);
    }

    /** Infinitely sharp edges (boundaries included) at the origin of h, around its fan. */
    static int infSharpEdges(Level level, int h) {
        int count = 0, g = h;
        while (true) {
            int gp = level.prev(g), t = level.hTwin[gp];
            if (Crease.isInfinite(level.edgeSharpness(gp))) count++;
            if (t < 0) break;
            if (t == h) return count;
            g = t;
        }
        g = h;
        while (true) {
            if (Crease.isInfinite(level.edgeSharpness(g))) count++;
            int t = level.hTwin[g];
            if (t < 0) break;
            g = level.next(t);
        }
        return count;
    }

    /** As {@link #corner(Level, int, int)}, the fan ending at infinitely sharp edges if {@code cut}. */
    static int corner(Level level, int h, int reg, boolean cut) {
        int faces = 0, g = h;
        boolean open = false;
        while (true) { // counter-clockwise
            faces++;
            if (reg > 0 && level.faceSize(level.face(g)) != reg) return -1;
            int gp = level.prev(g), t = across(level, gp, cut);
            if (t < 0) {
                open = true;
                break;
            }
            if (reg > 0 && Crease.isSharp(level.edgeSharpness(gp))) return -1;
            if (t == h) break;
            g = t;
        }
        if (open) {
            g = h;
            while (true) { // clockwise from h
                int t = across(level, g, cut);
                if (reg > 0 && t >= 0 && Crease.isSharp(level.edgeSharpness(g))) return -1;
                if (t < 0) break;
                g = level.next(t);
                faces++;
                if (reg > 0 && level.faceSize(level.face(g)) != reg) return -1;
            }
        }
        return faces << 1 | (open ? 1 : 0);
    }

    // ------------------------------------------------------------------ construction

    /** Quad lattice directions, counter-clockwise from (1,0). */
    private static final int[] QX = {1, 0, -1, 0}, QY = {0, 1, 0, -1};
    /** Triangle lattice directions, counter-clockwise from (1,0) (the third axis is (-1,1)). */
    private static final int[] TX = {1, 0, -1, -1, 0, 1}, TY = {0, 1, 1, 0, -1, -1};
    /** Box-spline point index of lattice point (x,y), x and y in -1..2, at [(y+1)*4 + x+1]; -1 outside. */
    private static final int[] TRI_INDEX = {
        -1, 0, 1, 2,
        3, 4, 5, 6,
        7, 8, 9, -1,
        10, 11, -1, -1};

    /**
     * The points of the regular neighbourhood of a face in lattice coordinates: the face's corner
     * c sits at (cx[c], cy[c]) and leaves it along direction dir[c] of the lattice's directions
     * (dx, dy); the faces around each corner are walked both ways, each contributing the points
     * it has at known lattice offsets. Writes vertex indices to {@code grid[(y+1)*4 + x+1]} for
     * x, y in -1..2, leaving -1 where there is no point.
     */
    private static int[] lattice(Level level, int f, int[] cx, int[] cy, int[] dir, int[] dx, int[] dy, boolean cut) {
        int[] grid = new int[16];
        java.util.Arrays.fill(grid, -1);
        int m = dx.length, size = cx.length, h0 = level.firstHalf(f);
        for (int c = 0; c < size; c++) {
            int corner = h0 + c;
            put(grid, cx[c], cy[c], level.hOrig[corner]);
            // Counter-clockwise: g runs from the corner in direction k.
            int g = corner, k = dir[c];
            for (int step = 0; step < m; step++) {
                collect(level, grid, g, cx[c], cy[c], k, dx, dy);
                int t = across(level, level.prev(g), cut);
                if (t < 0 || t == corner) break;
                g = t;
                k = (k + 1) % m;
            }
            // Clockwise, on a boundary (inside, the walk above went all the way round).
            g = corner;
            k = dir[c];
            for (int step = 0; step < m; step++) {
                int t = across(level, g, cut);
                if (t < 0) break;
                g = level.next(t);
                if (g == corner) break;
                k = (k + m - 1) % m;
                collect(level, grid, g, cx[c], cy[c], k, dx, dy);
            }
        }
        return grid;
    }

    /** The points of the face of half-edge g, which leaves the lattice point (x,y) in direction k. */
    private static void collect(Level level, int[] grid, int g, int x, int y, int k, int[] dx, int[] dy) {
        int m = dx.length, k1 = (k + 1) % m;
        put(grid, x + dx[k], y + dy[k], level.dest(g));
        put(grid, x + dx[k1], y + dy[k1], level.hOrig[level.prev(g)]);
        if (m == 4) put(grid, x + dx[k] + dx[k1], y + dy[k] + dy[k1], level.hOrig[level.next(level.next(g))]);
    }

    private static void put(int[] grid, int x, int y, int v) {
        if (x < -1 || x > 2 || y < -1 || y > 2) return;
        int i = (y + 1) * 4 + x + 1;
        if (grid[i] >= 0 && grid[i] != v) throw new IllegalStateException("inconsistent regular neighbourhood");
        grid[i] = v;
    }

    private static FaceSurface bSpline(Level level, double[] pos, int f, boolean cut) {
        int[] grid = lattice(level, f, new int[] {0, 1, 1, 0}, new int[] {0, 0, 1, 1}, new int[] {0, 1, 2, 3}, QX, QY, cut);
        int h0 = level.firstHalf(f);
        int mask = 0;
        for (int e = 0; e < 4; e++) if (across(level, h0 + e, cut) < 0) mask |= 1 << e;
        double[] cp = new double[48];
        int corner0 = level.hOrig[h0];
        for (int i = 0; i < 16; i++) {
            int r = i >> 2, c = i & 3;
            boolean phantom = (r == 0 && (mask & 1) != 0) || (c == 3 && (mask & 2) != 0) || (r == 3 && (mask & 4) != 0) || (c == 0 && (mask & 8) != 0);
            int v = grid[i];
            if (v < 0) {
                if (!phantom) throw new IllegalStateException("face " + f + ": point " + i + " of its B-spline patch is missing");
                v = corner0; // weight 0 once the boundary is folded in
            }
            System.arraycopy(pos, 3 * v, cp, 3 * i, 3);
        }
        return new FaceSurface(BSPLINE, cp, mask, 4);
    }

    private static FaceSurface boxSpline(Level level, double[] pos, int f, boolean cut) {
        int[] grid = lattice(level, f, new int[] {0, 1, 0}, new int[] {0, 0, 1}, new int[] {0, 2, 4}, TX, TY, cut);
        double[] cp = new double[36];
        boolean[] have = new boolean[12];
        for (int i = 0; i < 16; i++) {
            int p = TRI_INDEX[i];
            if (p >= 0 && grid[i] >= 0) {
                System.arraycopy(pos, 3 * grid[i], cp, 3 * p, 3);
                have[p] = true;
            }
        }
        int h0 = level.firstHalf(f);
        boolean[] edge = new boolean[3], vert = new boolean[3];
        int edges = 0;
        for (int c = 0; c < 3; c++) {
            edge[c] = across(level, h0 + c, cut) < 0;
            if (edge[c]) edges++;
            vert[c] = (corner(level, h0 + c, 0, cut) & 1) != 0;
        }
        // Phantom points beyond each boundary edge.
        for (int e = 0; e < 3; e++) {
            if (!edge[e]) continue;
            boolean before = edge[(e + 2) % 3], after = edge[(e + 1) % 3];
            phantom(cp, have, e, 0, -1, 0, 0, before ? 0 : -1, before ? 0 : 0, before ? 0 : -1, before ? 1 : 1);
            phantom(cp, have, e, 1, -1, 0, 0, 1, 0, 0, 1);
            phantom(cp, have, e, 2, -1, 1, 0, after ? 1 : 2, 0, after ? 0 : 1, 1);
        }
        // Boundary vertices not on a boundary edge of the face: all of them if it has none, the
        // one opposite its boundary edge if it has one and all three corners are on boundaries.
        for (int c = 0; c < 3; c++) {
            boolean apply = edges == 0 ? vert[c] : edges == 1 && vert[0] && vert[1] && vert[2] && edge[(c + 1) % 3];
            if (!apply) continue;
            phantom(cp, have, c, -1, 0, 0, 0, -1, 1, 0, 1);
            phantom(cp, have, c, 0, -1, 0, 0, 1, -1, 1, 0);
        }
        for (int p = 0; p < 12; p++) if (!have[p]) throw new IllegalStateException("face " + f + ": point " + p + " of its box-spline patch is missing");
        return new FaceSurface(BOX_SPLINE, cp, 0, 3);
    }

    /**
     * Sets the box-spline point at lattice (tx,ty), rotated r times about the face (corner k to
     * corner k+1), to the point at a plus the one at b minus the one at c (rotated the same way),
     * unless it exists already.
     */
    private static void phantom(double[] cp, boolean[] have, int r, int tx, int ty, int ax, int ay, int bx, int by, int cx, int cy) {
        int t = rotated(r, tx, ty);
        if (have[t]) return;
        int a = rotated(r, ax, ay), b = rotated(r, bx, by), c = rotated(r, cx, cy);
        if (!have[a] || !have[b] || !have[c]) throw new IllegalStateException("phantom point from a missing point");
        for (int d = 0; d < 3; d++) cp[3 * t + d] = cp[3 * a + d] + cp[3 * b + d] - cp[3 * c + d];
        have[t] = true;
    }

    /** Box-spline index of lattice point (x,y) after r rotations (x,y) -> (1 - x - y, x). */
    private static int rotated(int r, int x, int y) {
        for (int i = 0; i < r; i++) {
            int nx = 1 - x - y;
            y = x;
            x = nx;
        }
        int p = TRI_INDEX[(y + 1) * 4 + x + 1];
        if (p < 0) throw new IllegalStateException("lattice point (" + x + "," + y + ") is not in the patch");
        return p;
    }

    /**
     * The bilinear patch of a quad's corner points, or the bilinear sub-faces of any other
     * face's (xyz per corner, in the face's order; the array is kept).
     */
    static FaceSurface linear(double[] cornerPoints) {
        int n = cornerPoints.length / 3;
        return new FaceSurface(n == 4 ? BILINEAR : LINEAR_SUBFACES, cornerPoints, 0, n);
    }

    private static FaceSurface linear(Level level, double[] pos, int f) {
        int n = level.faceSize(f), h0 = level.firstHalf(f);
        double[] cp = new double[3 * n];
        for (int c = 0; c < n; c++) System.arraycopy(pos, 3 * level.hOrig[h0 + c], cp, 3 * c, 3);
        return new FaceSurface(n == 4 ? BILINEAR : LINEAR_SUBFACES, cp, 0, n);
    }

    // ------------------------------------------------------------------ evaluation

    /**
     * The limit position and its derivatives in u and v at (u,v) of the face's parameterization.
     * Any of the outputs may be null; each takes 3 values.
     */
    void evaluate(double u, double v, double[] position, double[] du, double[] dv) {
        switch (kind) {
            case BSPLINE -> evalBSpline(u, v, position, du, dv);
            case BOX_SPLINE -> evalBoxSpline(u, v, position, du, dv);
            case BILINEAR -> evalBilinear(u, v, cp[0], cp[1], cp[2], cp[3], cp[4], cp[5], cp[6], cp[7], cp[8], cp[9], cp[10], cp[11], 1, position, du, dv);
            default -> evalSubFace(u, v, position, du, dv);
        }
    }

    private void evalBSpline(double u, double v, double[] position, double[] du, double[] dv) {
        // Uniform cubic B-spline weights and derivatives in u (columns) and v (rows).
        double bu0 = bs(0, u), bu1 = bs(1, u), bu2 = bs(2, u), bu3 = bs(3, u);
        double du0 = dbs(0, u), du1 = dbs(1, u), du2 = dbs(2, u), du3 = dbs(3, u);
        double bv0 = bs(0, v), bv1 = bs(1, v), bv2 = bs(2, v), bv3 = bs(3, v);
        double dv0 = dbs(0, v), dv1 = dbs(1, v), dv2 = dbs(2, v), dv3 = dbs(3, v);
        // A boundary edge's phantom row or column is 2 B - I: fold its weight onto B and I.
        if ((boundary & 1) != 0) { bv1 += 2 * bv0; bv2 -= bv0; bv0 = 0; dv1 += 2 * dv0; dv2 -= dv0; dv0 = 0; }
        if ((boundary & 4) != 0) { bv2 += 2 * bv3; bv1 -= bv3; bv3 = 0; dv2 += 2 * dv3; dv1 -= dv3; dv3 = 0; }
        if ((boundary & 8) != 0) { bu1 += 2 * bu0; bu2 -= bu0; bu0 = 0; du1 += 2 * du0; du2 -= du0; du0 = 0; }
        if ((boundary & 2) != 0) { bu2 += 2 * bu3; bu1 -= bu3; bu3 = 0; du2 += 2 * du3; du1 -= du3; du3 = 0; }
        for (int d = 0; d < 3; d++) {
            double p = 0, pu = 0, pv = 0;
            for (int r = 0; r < 4; r++) {
                int o = 12 * r + d;
                double a = cp[o], b = cp[o + 3], c = cp[o + 6], e = cp[o + 9];
                double row = bu0 * a + bu1 * b + bu2 * c + bu3 * e;
                double rowU = du0 * a + du1 * b + du2 * c + du3 * e;
                double wv = r == 0 ? bv0 : r == 1 ? bv1 : r == 2 ? bv2 : bv3;
                double wdv = r == 0 ? dv0 : r == 1 ? dv1 : r == 2 ? dv2 : dv3;
                p += wv * row;
                pu += wv * rowU;
                pv += wdv * row;
            }
            if (position != null) position[d] = p;
            if (du != null) du[d] = pu;
            if (dv != null) dv[d] = pv;
        }
    }

    /** Uniform cubic B-spline basis function i at t in [0,1]. */
    static double bs(int i, double t) {
        double s = 1 - t;
        return switch (i) {
            case 0 -> s * s * s / 6;
            case 1 -> (3 * t * t * t - 6 * t * t + 4) / 6;
            case 2 -> (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6;
            default -> t * t * t / 6;
        };
    }

    static double dbs(int i, double t) {
        double s = 1 - t;
        return switch (i) {
            case 0 -> -s * s / 2;
            case 1 -> (3 * t * t - 4 * t) / 2;
            case 2 -> (-3 * t * t + 2 * t + 1) / 2;
            default -> t * t / 2;
        };
    }

    /**
     * The quartic box-spline basis of the regular Loop patch: 12 times the weight of point i is
     * the polynomial sum of BOX[i][k] s^EX[k] t^EY[k] (the three-direction box spline's pieces
     * over the 12 points' lattice offsets).
     */
    private static final int[] EX = {0, 1, 0, 2, 1, 0, 3, 2, 1, 0, 4, 3, 2, 1, 0};
    private static final int[] EY = {0, 0, 1, 0, 1, 2, 0, 1, 2, 3, 0, 1, 2, 3, 4};
    private static final int[][] BOX = {
        {1, -2, -4, 0, 6, 6, 2, 0, -6, -4, -1, -2, 0, 2, 1},
        {1, 2, -2, 0, -6, 0, -4, 0, 6, 2, 2, 4, 0, -2, -1},
        {0, 0, 0, 0, 0, 0, 2, 0, 0, 0, -1, -2, 0, 0, 0},
        {1, -4, -2, 6, 6, 0, -4, -6, 0, 2, 1, 2, 0, -2, -1},
        {6, 0, 0, -12, -12, -12, 8, 12, 12, 8, -1, -2, 0, -2, -1},
        {1, 4, 2, 6, 6, 0, -4, -6, -12, -4, -1, -2, 0, 4, 2},
        {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 0, 0, 0},
        {1, -2, 2, 0, -6, 0, 2, 6, 0, -4, -1, -2, 0, 4, 2},
        {1, 2, 4, 0, 6, 6, -4, -12, -6, -4, 2, 4, 0, -2, -1},
        {0, 0, 0, 0, 0, 0, 2, 6, 6, 2, -1, -2, 0, -2, -1},
        {0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 0, 0, -2, -1},
        {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 1}};

    private void evalBoxSpline(double s, double t, double[] position, double[] du, double[] dv) {
        double s2 = s * s, s3 = s2 * s, s4 = s3 * s, t2 = t * t, t3 = t2 * t, t4 = t3 * t;
        double px = 0, py = 0, pz = 0, ux = 0, uy = 0, uz = 0, vx = 0, vy = 0, vz = 0;
        for (int k = 0; k < 15; k++) {
            int a = EX[k], b = EY[k];
            double sa = a == 0 ? 1 : a == 1 ? s : a == 2 ? s2 : a == 3 ? s3 : s4;
            double tb = b == 0 ? 1 : b == 1 ? t : b == 2 ? t2 : b == 3 ? t3 : t4;
            double sa1 = a == 1 ? 1 : a == 2 ? s : a == 3 ? s2 : a == 4 ? s3 : 0;
            double tb1 = b == 1 ? 1 : b == 2 ? t : b == 3 ? t2 : b == 4 ? t3 : 0;
            double w = sa * tb, ws = a * sa1 * tb, wt = b * sa * tb1;
            double x = poly[3 * k], y = poly[3 * k + 1], z = poly[3 * k + 2];
            px += w * x; py += w * y; pz += w * z;
            ux += ws * x; uy += ws * y; uz += ws * z;
            vx += wt * x; vy += wt * y; vz += wt * z;
        }
        set(position, px, py, pz);
        set(du, ux, uy, uz);
        set(dv, vx, vy, vz);
    }

    private void evalSubFace(double u, double v, double[] position, double[] du, double[] dv) {
        // Bfr's tiles: a coordinate just past a tile's half (beyond 3/4) belongs to the next one.
        int ut = (int) u, vt = (int) v;
        double uf = u - ut, vf = v - vt;
        if (uf > 0.75) { ut++; uf -= 1; }
        if (vf > 0.75) { vt++; vf -= 1; }
        int q = columns * vt + ut;
        if (q < 0 || q >= n) throw new IllegalArgumentException("(" + u + ", " + v + ") is outside the face's sub-faces");
        int next = (q + 1) % n, prev = (q + n - 1) % n;
        double cx = 0, cy = 0, cz = 0;
        for (int i = 0; i < n; i++) { cx += cp[3 * i]; cy += cp[3 * i + 1]; cz += cp[3 * i + 2]; }
        cx /= n; cy /= n; cz /= n;
        double ox = cp[3 * q], oy = cp[3 * q + 1], oz = cp[3 * q + 2];
        evalBilinear(2 * uf, 2 * vf,
                ox, oy, oz,
                (ox + cp[3 * next]) / 2, (oy + cp[3 * next + 1]) / 2, (oz + cp[3 * next + 2]) / 2,
                cx, cy, cz,
                (ox + cp[3 * prev]) / 2, (oy + cp[3 * prev + 1]) / 2, (oz + cp[3 * prev + 2]) / 2,
                2, position, du, dv);
    }

    /** Bilinear patch of corners a (0,0), b (1,0), c (1,1), d (0,1); derivatives scaled by k. */
    private static void evalBilinear(double s, double t,
            double ax, double ay, double az, double bx, double by, double bz,
            double cx, double cy, double cz, double dx, double dy, double dz,
            double k, double[] position, double[] du, double[] dv) {
        double w0 = (1 - s) * (1 - t), w1 = s * (1 - t), w2 = s * t, w3 = (1 - s) * t;
        set(position, w0 * ax + w1 * bx + w2 * cx + w3 * dx, w0 * ay + w1 * by + w2 * cy + w3 * dy, w0 * az + w1 * bz + w2 * cz + w3 * dz);
        // d/ds: (1-t)(b - a) + t(c - d); d/dt: (1-s)(d - a) + s(c - b)
        set(du, k * ((1 - t) * (bx - ax) + t * (cx - dx)), k * ((1 - t) * (by - ay) + t * (cy - dy)), k * ((1 - t) * (bz - az) + t * (cz - dz)));
        set(dv, k * ((1 - s) * (dx - ax) + s * (cx - bx)), k * ((1 - s) * (dy - ay) + s * (cy - by)), k * ((1 - s) * (dz - az) + s * (cz - bz)));
    }

    // ------------------------------------------------------------------ bounds

    /** Doubles of scratch space {@link #bounds} needs (the largest use: 25 points and 20 powers). */
    static final int BOUNDS_SCRATCH = 3 * 25 + 20;

    /**
     * Relative widening of a box, in ulps of the largest coordinate magnitude involved: the box's
     * own rounding and an evaluation's are each a few tens of ulps at most.
     */
    static final int BOUNDS_ULPS = 256;

    /**
     * A conservative box of the patch over [u0,u1] x [v0,v1] (in a sub-face for other faces than
     * quads): the box of control points whose convex hull holds the patch over the range,
     * widened by {@link #BOUNDS_ULPS}. See {@link LimitSurface.Evaluator#bounds}.
     *
     * @param scratch {@link #BOUNDS_SCRATCH} doubles
     * @return true (every kind of patch here has a box)
     */
    boolean bounds(double u0, double u1, double v0, double v1, double[] out, double[] scratch) {
        switch (kind) {
            case BSPLINE -> bezierBounds(u0, u1, v0, v1, out, scratch);
            case BOX_SPLINE -> bernsteinBounds(u0, u1, v0, v1, out, scratch);
            default -> cornerBounds(u0, u1, v0, v1, out, scratch);
        }
        return true;
    }

    /**
     * The B-spline patch's Bezier points over the range: phantom rows and columns made explicit
     * (2 B - I, rows first, then columns, which is the separable fold of the evaluation), each
     * row's B-spline segment turned into its Bezier points and cut to [u0,u1] by blossoming,
     * then each column likewise in v. Every step after the phantoms is a convex combination.
     */
    private void bezierBounds(double u0, double u1, double v0, double v1, double[] out, double[] s) {
        double[] g = s; // 16 points, xyz: [12 r + 3 c + d]
        System.arraycopy(cp, 0, g, 0, 48);
        for (int c = 0; c < 4; c++) {
            if ((boundary & 1) != 0) phantomPoint(g, c, c + 4, c + 8);
            if ((boundary & 4) != 0) phantomPoint(g, 12 + c, 8 + c, 4 + c);
        }
        for (int r = 0; r < 4; r++) {
            if ((boundary & 8) != 0) phantomPoint(g, 4 * r, 4 * r + 1, 4 * r + 2);
            if ((boundary & 2) != 0) phantomPoint(g, 4 * r + 3, 4 * r + 2, 4 * r + 1);
        }
        double magnitude = 0;
        for (int i = 0; i < 48; i++) magnitude = Math.max(magnitude, Math.abs(g[i]));
        for (int r = 0; r < 4; r++) for (int d = 0; d < 3; d++) cutSegment(g, 12 * r + d, 3, u0, u1, s, 48);
        for (int c = 0; c < 4; c++) for (int d = 0; d < 3; d++) cutSegment(g, 3 * c + d, 12, v0, v1, s, 48);
        box(g, 16, magnitude, out);
    }

    /** Point a := 2 b - c (xyz, point indices into g). */
    private static void phantomPoint(double[] g, int a, int b, int c) {
        for (int d = 0; d < 3; d++) g[3 * a + d] = 2 * g[3 * b + d] - g[3 * c + d];
    }

    /**
     * The four values g[o], g[o + step], g[o + 2 step], g[o + 3 step] of a uniform cubic B-spline
     * segment replaced by the Bezier points of its piece over [t0,t1], using 4 doubles of tmp at k.
     */
    private static void cutSegment(double[] g, int o, int step, double t0, double t1, double[] tmp, int k) {
        double p0 = g[o], p1 = g[o + step], p2 = g[o + 2 * step], p3 = g[o + 3 * step];
        // The segment's Bezier points over [0,1].
        double b0 = (p0 + 4 * p1 + p2) / 6, b1 = (2 * p1 + p2) / 3, b2 = (p1 + 2 * p2) / 3, b3 = (p1 + 4 * p2 + p3) / 6;
        // Point j of the piece over [t0,t1] is the blossom at (t0 x (3 - j), t1 x j).
        tmp[k] = blossom(b0, b1, b2, b3, t0, t0, t0);
        tmp[k + 1] = blossom(b0, b1, b2, b3, t0, t0, t1);
        tmp[k + 2] = blossom(b0, b1, b2, b3, t0, t1, t1);
        tmp[k + 3] = blossom(b0, b1, b2, b3, t1, t1, t1);
        for (int j = 0; j < 4; j++) g[o + j * step] = tmp[k + j];
    }

    /** The cubic Bezier's blossom at (a, b, c): de Casteljau with a different parameter per step. */
    private static double blossom(double b0, double b1, double b2, double b3, double a, double b, double c) {
        double x0 = lerp(b0, b1, a), x1 = lerp(b1, b2, a), x2 = lerp(b2, b3, a);
        double y0 = lerp(x0, x1, b), y1 = lerp(x1, x2, b);
        return lerp(y0, y1, c);
    }

    private static double lerp(double p, double q, double t) { return (1 - t) * p + t * q; }

    /**
     * The box-spline polynomial over the rectangle [u0,u1] x [v0,v1] in the tensor Bernstein
     * basis of degree 4 x 4 (its total degree is 4): the polynomial lies in the hull of those 25
     * coefficients over the whole rectangle, so also over its part in the triangle.
     */
    private void bernsteinBounds(double u0, double u1, double v0, double v1, double[] out, double[] s) {
        // Powers 0..4 of u0, du, v0, dv at s[75..95).
        double du = u1 - u0, dv = v1 - v0;
        powers(s, 75, u0);
        powers(s, 80, du);
        powers(s, 85, v0);
        powers(s, 90, dv);
        // q[5 i + j], xyz: the coefficient of a^i b^j after s = u0 + du a, t = v0 + dv b.
        double[] q = s;
        java.util.Arrays.fill(q, 0, 75, 0.0);
        double magnitude = 0;
        for (int k = 0; k < 15; k++) {
            int ex = EX[k], ey = EY[k];
            for (int d = 0; d < 3; d++) magnitude += Math.abs(poly[3 * k + d]);
            for (int i = 0; i <= ex; i++) {
                double wu = BINOMIAL[ex][i] * s[75 + ex - i] * s[80 + i];
                for (int j = 0; j <= ey; j++) {
                    double w = wu * BINOMIAL[ey][j] * s[85 + ey - j] * s[90 + j];
                    for (int d = 0; d < 3; d++) q[3 * (5 * i + j) + d] += w * poly[3 * k + d];
                }
            }
        }
        // Power to Bernstein in b (each row i), then in a (each column j).
        for (int i = 0; i < 5; i++) for (int d = 0; d < 3; d++) toBernstein(q, 15 * i + d, 3, s, 75);
        for (int j = 0; j < 5; j++) for (int d = 0; d < 3; d++) toBernstein(q, 3 * j + d, 15, s, 75);
        box(q, 25, magnitude, out);
    }

    /** x^0 .. x^4 into s[k .. k+5). */
    private static void powers(double[] s, int k, double x) {
        s[k] = 1;
        for (int i = 1; i < 5; i++) s[k + i] = s[k + i - 1] * x;
    }

    private static final double[][] BINOMIAL = {{1}, {1, 1}, {1, 2, 1}, {1, 3, 3, 1}, {1, 4, 6, 4, 1}};

    /** Degree-4 power coefficients g[o + i step] (i = 0..4) replaced by their Bernstein coefficients over [0,1]. */
    private static void toBernstein(double[] g, int o, int step, double[] tmp, int k) {
        for (int b = 0; b < 5; b++) {
            double acc = 0;
            for (int i = 0; i <= b; i++) acc += BINOMIAL[b][i] / BINOMIAL[4][i] * g[o + i * step];
            tmp[k + b] = acc;
        }
        for (int b = 0; b < 5; b++) g[o + b * step] = tmp[k + b];
    }

    /** Bilinear faces: the box of the range's four corners (a bilinear patch lies in their hull). */
    private void cornerBounds(double u0, double u1, double v0, double v1, double[] out, double[] s) {
        // Corner k evaluated into s[0..3), then kept at s[3 + 3k].
        for (int k = 0; k < 4; k++) {
            evaluate(k == 0 || k == 3 ? u0 : u1, k < 2 ? v0 : v1, s, null, null);
            System.arraycopy(s, 0, s, 3 + 3 * k, 3);
        }
        System.arraycopy(s, 3, s, 0, 12);
        box(s, 4, 0, out);
    }

    /** The box of n points (xyz in g), widened by {@link #BOUNDS_ULPS} ulps of the larger of magnitude and the points' own. */
    private static void box(double[] g, int n, double magnitude, double[] out) {
        double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
        for (int i = 0; i < n; i++) {
            double x = g[3 * i], y = g[3 * i + 1], z = g[3 * i + 2];
            x0 = Math.min(x0, x); x1 = Math.max(x1, x);
            y0 = Math.min(y0, y); y1 = Math.max(y1, y);
            z0 = Math.min(z0, z); z1 = Math.max(z1, z);
        }
        double m = Math.max(magnitude, Math.max(Math.max(Math.abs(x0), Math.abs(x1)), Math.max(Math.max(Math.abs(y0), Math.abs(y1)), Math.max(Math.abs(z0), Math.abs(z1)))));
        double pad = BOUNDS_ULPS * Math.ulp(m);
        out[0] = x0 - pad; out[1] = y0 - pad; out[2] = z0 - pad;
        out[3] = x1 + pad; out[4] = y1 + pad; out[5] = z1 + pad;
    }

    private static void set(double[] out, double x, double y, double z) {
        if (out == null) return;
        out[0] = x;
        out[1] = y;
        out[2] = z;
    }
}
