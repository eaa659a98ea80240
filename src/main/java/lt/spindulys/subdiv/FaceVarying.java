package lt.spindulys.subdiv;

/**
 * Face-varying data (UVs) as a mesh of its own: the <i>value mesh</i>. It has the same faces and
 * the same half-edge layout as the geometry, but its vertices are the distinct (vertex, UV
 * index) pairs, so a UV seam is a boundary of the value mesh. Refining it with the ordinary
 * topology and masks reproduces Far's face-varying rules: values continuous across an edge are
 * smoothed like the vertices, seams behave as infinitely sharp boundaries, and the
 * {@link SubdivOptions.FaceVarying} option decides which values are pinned (made corners).
 * With {@code ALL} (Far's default, FVAR_LINEAR_ALL) every value is interpolated bilinearly.
 *
 * <p>Sharpness of the value mesh is the geometry's (taken through the shared half-edge
 * numbering at every level), so creases shape UVs as they shape positions.
 */
final class FaceVarying {
    private FaceVarying() {}

    /**
     * A value mesh level with the UVs of its vertices. A linear channel's levels after the
     * first carry only faces and edges (no twins, rings or tags): bilinear refinement needs no
     * more.
     */
    record Channel(Level level, double[] values, boolean linear, boolean linearBoundaries) {
        Channel refine(Level geomChild, SubdivOptions opt) {
            boolean chaikin = opt.creasing() == SubdivOptions.Creasing.CHAIKIN;
            Level c = linear ? Refinement.refineCornersAndEdges(level) : Refinement.refine(level, chaikin, geomChild);
            if (linearBoundaries && !linear) pinBoundaries(c);
            if (!linear) refineDependents(level, c);
            double[] cv = new double[2 * c.nV];
            PrimvarRefiner.interpolate(level, c, opt, 2, values, cv, linear);
            return new Channel(c, cv, linear, linearBoundaries);
        }
    }

    static Channel build(Level geom, int[] faceSizes, int[] faceUv, double[] uv, SubdivOptions opt) {
        int nV = geom.nV, nH = geom.nH;
        // Value vertices: the distinct UV indices at each vertex, numbered vertex by vertex.
        int[] count = new int[nV + 1];
        for (int h = 0; h < nH; h++) count[geom.hOrig[h] + 1]++;
        for (int v = 0; v < nV; v++) count[v + 1] += count[v];
        int[] byVertex = new int[nH];
        int[] fill = count.clone();
        for (int h = 0; h < nH; h++) byVertex[fill[geom.hOrig[h]]++] = h;
        int[] valueOf = new int[nH];
        int[] valueVertex = new int[nH];
        int[] valueUv = new int[nH];
        int nValues = 0;
        for (int v = 0; v < nV; v++) {
            int first = nValues;
            for (int i = count[v]; i < count[v + 1]; i++) {
                int h = byVertex[i], u = faceUv[h];
                int id = -1;
                for (int j = first; j < nValues; j++) {
                    if (valueUv[j] == u) {
                        id = j;
                        break;
                    }
                }
                if (id < 0) {
                    id = nValues++;
                    valueUv[id] = u;
                    valueVertex[id] = v;
                }
                valueOf[h] = id;
            }
        }
        double[] values = new double[2 * nValues];
        for (int id = 0; id < nValues; id++) {
            values[2 * id] = uv[2 * valueUv[id]];
            values[2 * id + 1] = uv[2 * valueUv[id] + 1];
        }
        BaseLevelBuilder levelBuilder = new BaseLevelBuilder(nValues, faceSizes, valueOf, geom.faceStart != null);
        Level lv = levelBuilder.level;
        lv.triangleSplit = geom.triangleSplit;
        SubdivOptions.FaceVarying fv = opt.fvar();
        // Bilinear refinement interpolates every value linearly, whatever the option says.
        boolean linear = fv == SubdivOptions.FaceVarying.ALL || opt.scheme() == SubdivOptions.Scheme.BILINEAR;
        boolean linearBoundaries = linear || fv == SubdivOptions.FaceVarying.BOUNDARIES;
        if (linear) {
            levelBuilder.tag(SubdivOptions.Boundary.EDGE_ONLY, null, null, null, null);
            return new Channel(lv, values, true, true);
        }

        // Sharpness from the geometry: edges continuous in UV keep the geometry's sharpness
        // (infinite where the geometry edge is a boundary or non-manifold).
        float[] eSharp = new float[lv.nE];
        boolean anyE = false;
        for (int h = 0; h < nH; h++) {
            if (!lv.primary(h) || lv.hTwin[h] < 0) continue;
            float s = geom.edgeSharpness(h);
            eSharp[lv.edge(h)] = s;
            anyE |= s != 0f;
        }
        float[] vSharp = null;
        if (geom.vSharp != null) {
            vSharp = new float[nValues];
            for (int id = 0; id < nValues; id++) vSharp[id] = geom.vSharp[valueVertex[id]];
        }

        // Far's "mismatched" vertices: an incident edge is discontinuous in UV, or boundary
        // rules for UVs differ from those for positions there.
        boolean[] mismatch = new boolean[nV];
        for (int h = 0; h < nH; h++) {
            if (geom.hTwin[h] >= 0 && lv.hTwin[h] < 0) {
                mismatch[geom.hOrig[h]] = true;
                mismatch[geom.dest(h)] = true;
            }
        }
        for (int i = 0; i < geom.nmEdge.length; i++) {
            int h0 = geom.nmEdgeHalf[geom.nmEdgeStart[i]];
            for (int j = geom.nmEdgeStart[i] + 1; j < geom.nmEdgeStart[i + 1]; j++) {
                if (lv.edge(geom.nmEdgeHalf[j]) != lv.edge(h0)) {
                    mismatch[geom.hOrig[h0]] = true;
                    mismatch[geom.dest(h0)] = true;
                }
            }
        }
        boolean cornersSharp = fv != SubdivOptions.FaceVarying.NONE;
        boolean smoothGeomCorners = opt.boundary() != SubdivOptions.Boundary.EDGE_AND_CORNER;
        boolean dependent = fv == SubdivOptions.FaceVarying.CORNERS_PLUS1 || fv == SubdivOptions.FaceVarying.CORNERS_PLUS2;
        boolean plus2 = fv == SubdivOptions.FaceVarying.CORNERS_PLUS2;
        boolean sharpenDarts = plus2 || linearBoundaries;
        int[] geomFaces = new int[nV], valueFaces = new int[nValues], valuesAt = new int[nV];
        for (int h = 0; h < nH; h++) {
            geomFaces[geom.hOrig[h]]++;
            valueFaces[valueOf[h]]++;
        }
        for (int id = 0; id < nValues; id++) valuesAt[valueVertex[id]]++;
        for (int v = 0; v < nV; v++) {
            boolean boundary = (geom.tag(v) & Level.T_BOUNDARY) != 0;
            if (boundary && !mismatch[v]) {
                if (linearBoundaries && geomFaces[v] > 0) mismatch[v] = true;
                else if (geomFaces[v] == 1 && smoothGeomCorners && cornersSharp) mismatch[v] = true;
            }
        }
        boolean[] pin = new boolean[nValues];
        int[] depOn = null;
        for (int first = 0; first < nValues; ) {
            int v = valueVertex[first], n = valuesAt[v], end = first + n;
            if (mismatch[v]) {
                int gt = geom.tag(v);
                boolean all = linearBoundaries || (gt & (Level.T_INF_SHARP | Level.T_NONMANIFOLD)) != 0
                        || (dependent && n > 2)
                        || (sharpenDarts && n == 1 && (gt & Level.T_BOUNDARY) == 0);
                if (!all && dependent && n == 2) {
                    all = disjoint(lv, eSharp, first) || disjoint(lv, eSharp, first + 1);
                    if (plus2) all |= valueFaces[first] == 1 || valueFaces[first + 1] == 1;
                }
                for (int id = first; id < end; id++) pin[id] = all || (valueFaces[id] == 1 && cornersSharp);
                // Far's dependent sharpness: of two values, one whose span has no semi-sharp edge
                // while the other's has one stays a corner as long as the other does, then
                // blends into its crease with the other's weight.
                if (!all && dependent && n == 2 && geom.vertexSharpness(v) == 0f) {
                    boolean s0 = spanHas(lv, eSharp, first, false), s1 = spanHas(lv, eSharp, first + 1, false);
                    if (s0 != s1) {
                        int a = s0 ? first + 1 : first, b = s0 ? first : first + 1;
                        if (!pin[a]) {
                            if (depOn == null) {
                                depOn = new int[nValues];
                                java.util.Arrays.fill(depOn, -1);
                            }
                            depOn[a] = b;
                        }
                    }
                }
            }
            first = end;
        }
        levelBuilder.tag(SubdivOptions.Boundary.EDGE_ONLY, anyE ? eSharp : null, vSharp, pin, null);
        if (depOn != null) {
            lv.depOn = depOn;
            for (int a = 0; a < nValues; a++) {
                if (depOn[a] >= 0) lv.vTag[a] = (byte) ((lv.vTag[a] & ~Level.T_RULE) | Crease.RULE_CORNER);
            }
        }
        return new Channel(lv, values, false, linearBoundaries);
    }

    /**
     * Far's "disjoint" value span: split by a seam or an infinitely sharp edge. The level's tags
     * are not set yet, so the edges' sharpness comes from {@code eSharp} (by edge of the value mesh).
     */
    private static boolean disjoint(Level lv, float[] eSharp, int id) {
        return lv.nmVertIndex(id) >= 0 || spanHas(lv, eSharp, id, true);
    }

    /** Whether a value's span holds an edge (inside it: not a seam) that is infinitely sharp, or else semi-sharp. */
    private static boolean spanHas(Level lv, float[] eSharp, int id, boolean infinite) {
        int start = lv.vOut[id], h = start;
        do {
            if (lv.hTwin[h] >= 0) {
                float s = eSharp[lv.edge(h)];
                if (infinite ? Crease.isInfinite(s) : Crease.isSemiSharp(s)) return true;
            }
            int t = lv.hTwin[lv.prev(h)];
            if (t < 0) break;
            h = t;
        } while (h != start);
        return false;
    }

    /**
     * The child's dependent values (see {@link Level#depOn}): a value stays a corner while the
     * value it depends on stays sharp through semi-sharp edges; otherwise it takes the rule of its
     * own edges and no longer depends on the other.
     */
    static void refineDependents(Level p, Level c) {
        if (p.depOn == null) return;
        int[] dep = new int[c.nV];
        java.util.Arrays.fill(dep, -1);
        boolean any = false;
        int[] ring = null;
        for (int a = 0; a < p.nV; a++) {
            int b = p.depOn[a];
            if (b < 0) continue;
            boolean stillSharp = c.rule(b) == Crease.RULE_CORNER && (c.tag(b) & Level.T_SEMI_EDGES) != 0;
            int rule;
            if (stillSharp) {
                rule = Crease.RULE_CORNER;
                dep[a] = b;
                any = true;
            } else {
                if (ring == null) ring = new int[c.maxValence() + 2];
                int n = c.ring(a, ring), edges = c.hTwin[c.vOut[a]] < 0 ? n + 1 : n, sharp = 0;
                for (int j = 0; j < edges; j++) if (Crease.isSharp(c.edgeSharpness(ring[j]))) sharp++;
                rule = Crease.vertexRule(c.vertexSharpness(a), sharp);
            }
            c.vTag[a] = (byte) ((c.vTag[a] & ~Level.T_RULE) | rule);
        }
        c.depOn = any ? dep : null;
    }

    /** Linear boundaries: every value on a UV boundary becomes a corner. */
    static void pinBoundaries(Level c) {
        if (c.vTag == null) return;
        for (int v = 0; v < c.nV; v++) {
            if ((c.vTag[v] & Level.T_BOUNDARY) != 0) {
                if (c.vSharp == null) c.vSharp = new float[c.nV];
                c.vSharp[v] = Crease.INFINITE;
                c.vTag[v] = (byte) ((c.vTag[v] & ~(Level.T_RULE | Level.T_SEMI_SHARP)) | Crease.RULE_CORNER | Level.T_INF_SHARP);
            }
        }
    }
}
