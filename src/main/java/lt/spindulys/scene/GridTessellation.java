package lt.spindulys.scene;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicLong;
import java.util.stream.IntStream;

import lt.spindulys.accel.Accelerator;
import lt.spindulys.accel.BoxList;
import lt.spindulys.accel.GridPatch;
import lt.spindulys.accel.GridPieces;
import lt.spindulys.accel.PrimitiveHit;
import lt.spindulys.accel.PrimitiveSet;
import lt.spindulys.accel.PrimitiveVisitor;
import lt.spindulys.accel.TraversalScratch;
import lt.spindulys.adaptive.CachedPatch;
import lt.spindulys.adaptive.EdgeRates;
import lt.spindulys.adaptive.FacePattern;
import lt.spindulys.adaptive.GridPattern;
import lt.spindulys.adaptive.PatchCache;
import lt.spindulys.adaptive.PatchSource;
import lt.spindulys.adaptive.RecentPatches;
import lt.spindulys.adaptive.TrianglePattern;
import lt.spindulys.limits.HeapBudget;
import lt.spindulys.math.Placement;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.LimitSurface;
import lt.spindulys.subdiv.PatchRefiner;
import lt.spindulys.subdiv.SubdivOptions;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;
import lt.spindulys.trace.TraceContext;

/**
 * The tessellation of one adaptive subdivision surface at integer rates per control edge, on the
 * limit surface: each control edge gets a number of segments from its projected length (the same
 * for both faces beside it), each face a grid whose resolution comes from its own edges
 * ({@link FacePattern}: a quad's grid, an n-gon's quad sub-faces; {@link TrianglePattern} for a
 * Loop triangle), with its vertices on coarser edges snapped to the edge's own points, and every
 * grid vertex evaluated on the limit surface directly ({@link LimitSurface}), not refined to.
 *
 * <p><b>Watertight.</b> A point shared by several faces (a control vertex, a point of a control
 * edge, a point of an n-gon's spoke or its centre) is evaluated once, from one face (the first
 * that has it), when the tessellation is finished, and every grid that has it reads that one
 * value, so the floats on both sides of a shared edge are bit-identical and the watertight
 * triangle test leaves no crack. Only interior grid points are evaluated when a piece is built.
 *
 * <p><b>Pieces.</b> A face's grid is cut into pieces of at most {@value #PIECE_SIDE} vertices a
 * side ({@link GridPieces}), each a {@link GridPiece} (float vertices, implicit topology, a grid
 * hierarchy: {@link GridPatch}); a Loop face is one piece of triangles ({@link PatchTriangles}).
 * The structure over the surface has the pieces as primitives, bounded before they are built by
 * the Bezier hull of the piece's parameter range where the evaluator knows one (regular faces),
 * else by the face's one-ring hull, and by the piece's own vertices once built. The projected
 * method builds every piece when the scene is built; the lazy one each when a ray first reaches
 * its box, kept in the scene's bounded cache; the combined one pins pieces while the eager budget
 * lasts. Every piece is a pure function of the control mesh and the rates, so the image does not
 * depend on the cache or the number of threads.
 */
final class GridTessellation implements SurfaceTessellation, PrimitiveSet, PatchSource {
    /** Most vertices per piece side: 17 x 17 vertices, 512 triangles (Embree's grid size). */
    static final int PIECE_SIDE = GridPieces.DEFAULT_MAX_SIDE;

    private final PatchRefiner refiner;
    private final ControlMesh control;
    private final LimitSurface limit;
    private final boolean loop, smooth, uvs;
    private final AdaptiveSubdivisionSurface.Method method;
    private final int fixedLevel, maxLevel;
    private final double target;
    private final String name;
    private final List<Placement> placements = new ArrayList<>();
    private final List<Boolean> backHidden = new ArrayList<>();

    // ---- made by finish ----
    private AdaptiveSubdivisionSurface.Method used;
    private AcceleratorKind kind;
    private int[] rate;
    /** The two vertices of every control edge, which fix the order its shared points are stored in. */
    private int[] edgeVertex;
    /** Non-hole faces, and the first corner of every control face. */
    private int[] faces, cornerStart;
    /** Per entry of {@link #faces}: its pattern, its evaluator's level, its first grid. */
    private FacePattern[] quadPattern;
    private TrianglePattern[] triPattern;
    private int[] faceLevel, firstGrid;
    /** Per grid (a quad's grid or an n-gon's sub-face): its face (index into {@link #faces}), sub-face, cutting and first piece. */
    private int[] gridFace, gridSub, firstPiece;
    private GridPieces[] gridPieces;
    /** Per piece: its grid (for Loop, the face). */
    private int[] pieceGrid;
    private int pieceCount;
    /** Limit points shared between faces: per control vertex; per control edge its inner points; per n-gon its spokes' inner points and centre. */
    private double[] cornerPoint;
    private double[][] edgePoints, spokePoints;
    private int[] tight;
    private TessellationPiece[] pinned;
    private int pinnedCount;
    private long pinnedBytes, eagerBytes, triangles, zeroArea;
    private Accelerator top;
    private PatchCache cache;
    private PatchCache.Table table;
    private final AtomicLong unevaluated = new AtomicLong();
    private final PrimitiveVisitor crossingVisitor = this::visitPiece;

    GridTessellation(AdaptiveSubdivisionSurface s, double target) {
        AdaptiveSubdivisionSurface.Geometry geometry = s.geometry();
        refiner = geometry.refiner();
        control = refiner.control();
        limit = geometry.limit();
        loop = control.options().scheme() == SubdivOptions.Scheme.LOOP;
        uvs = control.uvs() != null;
        method = s.method();
        smooth = s.isSmooth();
        fixedLevel = s.fixedLevel();
        maxLevel = s.maxLevel();
        this.target = target;
        name = AdaptiveTessellation.displayName(s);
    }

    @Override
    public synchronized void addPlacement(Placement p, boolean hidden) {
        placements.add(p);
        backHidden.add(hidden);
    }

    @Override
    public boolean refinesWhileTracing() { return top != null && pinnedCount < pieceCount; }

    // ------------------------------------------------------------------ finishing

    @Override
    public void finish(BuildShared shared, BuildContext root) {
        kind = root.accelerator();
        edgeVertex = refiner.edgeVertices();
        int nf = refiner.faceCount();
        cornerStart = new int[nf + 1];
        for (int f = 0; f < nf; f++) cornerStart[f + 1] = cornerStart[f] + refiner.faceSize(f);
        chooseRates(shared);
        int count = 0;
        for (int f = 0; f < nf; f++) if (!refiner.isHole(f)) count++;
        faces = new int[count];
        for (int f = 0, k = 0; f < nf; f++) if (!refiner.isHole(f)) faces[k++] = f;
        makePatterns();
        tight = new int[6 * pieceCount];
        evaluateSharedPoints();
        used = method;
        if (method == AdaptiveSubdivisionSurface.Method.PROJECTED) {
            long need = 0;
            for (int p = 0; p < pieceCount; p++) need = HeapBudget.sum(need, pieceBytes(p));
            if (HeapBudget.fits(need) && shared.takeEager(need)) {
                pinned = new TessellationPiece[pieceCount];
                buildAll(pinned);
                pinnedCount = pieceCount;
                for (TessellationPiece p : pinned) pinnedBytes += p.bytes();
                eagerBytes = need;
                top = kind.build(this);
                return;
            }
            // Does not fit: build lazily instead, as the combined method does, within the budget.
            used = AdaptiveSubdivisionSurface.Method.COMBINED;
        }
        cache = shared.cache();
        table = cache.table(pieceCount, name);
        if (used == AdaptiveSubdivisionSurface.Method.COMBINED) pinWithinBudget(shared);
        top = kind.build(this);
    }

    /** Rates per control edge: from the view (the largest any placement needs) or 2^level everywhere; even around non-quads. */
    private void chooseRates(BuildShared shared) {
        int ne = refiner.edgeCount();
        rate = new int[ne];
        if (fixedLevel >= 0) {
            Arrays.fill(rate, EdgeRates.ofLevel(fixedLevel));
        } else {
            Arrays.fill(rate, 1);
            int[] ev = refiner.edgeVertices();
            int maxRate = EdgeRates.ofLevel(maxLevel);
            int[] own = new int[ne];
            for (int k = 0; k < placements.size(); k++) {
                Placement p = placements.get(k);
                Arrays.fill(own, 1);
                EdgeRates.perEdgeMax(shared.view(), control.positions(), ev, p, target, maxRate, AdaptiveTessellation.OFFSCREEN_SCALE, own);
                if (backHidden.get(k) && p.isStatic()) coarsenHidden(p.staticTransform(), shared.view().eye(), ev, own);
                for (int e = 0; e < ne; e++) rate[e] = Math.max(rate[e], own[e]);
            }
        }
        if (!loop) {
            int nf = refiner.faceCount();
            int[] sizes = new int[nf], edges = new int[cornerStart[nf]];
            for (int f = 0; f < nf; f++) {
                sizes[f] = refiner.faceSize(f);
                for (int k = 0; k < sizes[f]; k++) edges[cornerStart[f] + k] = refiner.faceEdge(f, k);
            }
            EdgeRates.evenAroundPolygons(sizes, edges, rate);
        }
    }

    /**
     * Divides by the offscreen scale the rates of edges the camera cannot see: edges whose every
     * face turns its back to the eye (by its control polygon, with a margin, so that faces near a
     * silhouette keep their rates) on a surface whose back faces are hidden. A face seen keeps
     * all its edges' rates, so no silhouette is coarsened.
     * Like Cycles' offscreen dicing: such parts are seen only in shadows and reflections.
     */
    private void coarsenHidden(Transform toWorld, double[] eye, int[] ev, int[] rates) {
        int nv = control.vertexCount(), nf = refiner.faceCount();
        double[] pos = control.positions(), world = new double[3 * nv];
        for (int v = 0; v < nv; v++) {
            lt.spindulys.math.Vec3 w = toWorld.point(new lt.spindulys.math.Vec3(pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]));
            world[3 * v] = w.x(); world[3 * v + 1] = w.y(); world[3 * v + 2] = w.z();
        }
        int[] fv = control.faceVertices();
        boolean[] seen = new boolean[rates.length];
        for (int f = 0; f < nf; f++) {
            int n = refiner.faceSize(f), c0 = cornerStart[f];
            // Newell's normal and the centroid of the control polygon.
            double nx = 0, ny = 0, nz = 0, cx = 0, cy = 0, cz = 0;
            for (int k = 0; k < n; k++) {
                int a = 3 * fv[c0 + k], b = 3 * fv[c0 + (k + 1) % n];
                nx += (world[a + 1] - world[b + 1]) * (world[a + 2] + world[b + 2]);
                ny += (world[a + 2] - world[b + 2]) * (world[a] + world[b]);
                nz += (world[a] - world[b]) * (world[a + 1] + world[b + 1]);
                cx += world[a] / n; cy += world[a + 1] / n; cz += world[a + 2] / n;
            }
            double vx = cx - eye[0], vy = cy - eye[1], vz = cz - eye[2];
            double nl = Math.sqrt(nx * nx + ny * ny + nz * nz), vl = Math.sqrt(vx * vx + vy * vy + vz * vz);
            boolean back = nl > 0 && vl > 0 && (nx * vx + ny * vy + nz * vz) > HIDDEN_MARGIN * nl * vl;
            if (!back) for (int k = 0; k < n; k++) seen[refiner.faceEdge(f, k)] = true;
        }
        for (int e = 0; e < rates.length; e++) {
            if (!seen[e]) rates[e] = (int) Math.ceil(rates[e] / AdaptiveTessellation.OFFSCREEN_SCALE);
        }
    }

    /** How far past edge-on (cosine of the angle to the eye) a control face must turn away to count as hidden. */
    static final double HIDDEN_MARGIN = 0.1;

    private int faceRate(int f, int k) { return rate[refiner.faceEdge(f, k)]; }

    /** Every face's pattern, its grids and their pieces. */
    private void makePatterns() {
        int n = faces.length;
        faceLevel = new int[n];
        firstGrid = new int[n + 1];
        if (loop) triPattern = new TrianglePattern[n];
        else quadPattern = new FacePattern[n];
        for (int i = 0; i < n; i++) {
            int f = faces[i], size = refiner.faceSize(f), max = 1;
            int[] r = new int[size];
            for (int k = 0; k < size; k++) max = Math.max(max, r[k] = faceRate(f, k));
            faceLevel[i] = LimitSurface.levelForRate(max);
            if (loop) {
                triPattern[i] = new TrianglePattern(r[0], r[1], r[2]);
                firstGrid[i + 1] = firstGrid[i] + 1;
                triangles = HeapBudget.sum(triangles, triPattern[i].triangleCount());
                zeroArea += triPattern[i].zeroAreaTriangles();
            } else {
                quadPattern[i] = FacePattern.polygon(r);
                firstGrid[i + 1] = firstGrid[i] + quadPattern[i].subFaceCount();
                triangles = HeapBudget.sum(triangles, quadPattern[i].triangleCount());
                zeroArea += quadPattern[i].zeroAreaTriangles();
            }
        }
        int grids = firstGrid[n];
        long pieceTotal = 0;
        for (int i = 0; i < n && !loop; i++) {
            for (int k = 0; k < quadPattern[i].subFaceCount(); k++) {
                GridPattern p = quadPattern[i].subFace(k);
                pieceTotal += (long) ceilDiv(p.columns(), PIECE_SIDE - 1) * ceilDiv(p.rows(), PIECE_SIDE - 1);
            }
        }
        if (loop) pieceTotal = n;
        // Per grid and per piece: their indices, boxes, slots in the cache and pinned references.
        HeapBudget.require(HeapBudget.sum(HeapBudget.product(grids, 64), HeapBudget.product(pieceTotal, 64)), "the " + pieceTotal + " grid pieces of " + name);
        gridFace = new int[grids];
        gridSub = new int[grids];
        firstPiece = new int[grids + 1];
        gridPieces = loop ? null : new GridPieces[grids];
        for (int i = 0; i < n; i++) {
            for (int g = firstGrid[i]; g < firstGrid[i + 1]; g++) {
                gridFace[g] = i;
                gridSub[g] = g - firstGrid[i];
                int pieces = 1;
                if (!loop) {
                    GridPattern p = quadPattern[i].subFace(gridSub[g]);
                    gridPieces[g] = new GridPieces(p.columns() + 1, p.rows() + 1, PIECE_SIDE);
                    pieces = gridPieces[g].count();
                }
                firstPiece[g + 1] = firstPiece[g] + pieces;
            }
        }
        pieceCount = firstPiece[grids];
        pieceGrid = new int[pieceCount];
        for (int g = 0; g < grids; g++) Arrays.fill(pieceGrid, firstPiece[g], firstPiece[g + 1], g);
    }

    private static int ceilDiv(int a, int b) { return (a + b - 1) / b; }

    // ------------------------------------------------------------------ shared points

    /** The face's (u, v) of a point of sub-face {@code sub} at its own (s, t) (an n-gon's sub-faces tile Bfr's layout). */
    private static void faceParameters(int n, int sub, double s, double t, double[] out) {
        if (n == 4) {
            out[0] = s;
            out[1] = t;
            return;
        }
        int columns = LimitSurface.subFaceColumns(n);
        out[0] = sub % columns + s / 2;
        out[1] = sub / columns + t / 2;
    }

    /** The face (u, v) of corner k, as the evaluator parameterizes the face. */
    private void cornerParameters(int f, int k, double[] uv) {
        int n = refiner.faceSize(f);
        if (loop) {
            uv[0] = k == 1 ? 1 : 0;
            uv[1] = k == 2 ? 1 : 0;
        } else if (n == 4) {
            uv[0] = k == 1 || k == 2 ? 1 : 0;
            uv[1] = k >= 2 ? 1 : 0;
        } else {
            int columns = LimitSurface.subFaceColumns(n);
            uv[0] = k % columns;
            uv[1] = k / columns;
        }
    }

    /** The face (u, v) of point c (0 to R, counted from corner k) of the face's edge k, of rate R. */
    private void edgeParameters(int f, int k, int c, int r, double[] uv) {
        int n = refiner.faceSize(f);
        double t = (double) c / r, rest = (double) (r - c) / r;
        if (loop) {
            switch (k) {
                case 0 -> { uv[0] = t; uv[1] = 0; }
                case 1 -> { uv[0] = rest; uv[1] = t; }
                default -> { uv[0] = 0; uv[1] = rest; }
            }
        } else if (n == 4) {
            switch (k) {
                case 0 -> { uv[0] = t; uv[1] = 0; }
                case 1 -> { uv[0] = 1; uv[1] = t; }
                case 2 -> { uv[0] = rest; uv[1] = 1; }
                default -> { uv[0] = 0; uv[1] = rest; }
            }
        } else {
            int half = r / 2, columns = LimitSurface.subFaceColumns(n);
            if (c <= half) {
                // The first half is edge 0 of sub-face k, from corner k.
                uv[0] = k % columns + (double) c / half / 2;
                uv[1] = k / columns;
            } else {
                // The second half is edge 3 of sub-face k + 1, which runs from the midpoint (t = 1) to corner k + 1 (t = 0).
                int s = (k + 1) % n;
                uv[0] = s % columns;
                uv[1] = s / columns + (double) (r - c) / half / 2;
            }
        }
    }

    /**
     * Evaluates every point that faces share, each once, from the first face that has it: the
     * control vertices' limit points, the inner points of every control edge at its rate, and of
     * every n-gon its spokes' inner points and centre; and, with the same evaluator of each face,
     * its pieces' boxes ({@link #boundPieces}).
     */
    private void evaluateSharedPoints() {
        int nv = control.vertexCount(), ne = refiner.edgeCount();
        long bytes = 24L * nv;
        for (int e = 0; e < ne; e++) bytes = HeapBudget.sum(bytes, 24L * Math.max(0, rate[e] - 1) + 16);
        HeapBudget.require(bytes, "the shared edge points of " + name);
        int[] vertexOwner = new int[nv], edgeOwner = new int[ne];
        Arrays.fill(vertexOwner, -1);
        Arrays.fill(edgeOwner, -1);
        int[] fv = control.faceVertices();
        for (int i = 0; i < faces.length; i++) {
            int f = faces[i];
            for (int k = 0; k < refiner.faceSize(f); k++) {
                int v = fv[cornerStart[f] + k], e = refiner.faceEdge(f, k);
                if (vertexOwner[v] < 0) vertexOwner[v] = i;
                if (edgeOwner[e] < 0) edgeOwner[e] = i;
            }
        }
        cornerPoint = new double[3 * nv];
        Arrays.fill(cornerPoint, Double.NaN);
        edgePoints = new double[ne][];
        spokePoints = new double[faces.length][];
        int[] ev = edgeVertex;
        IntStream.range(0, faces.length).parallel().forEach(i -> {
            int f = faces[i], n = refiner.faceSize(f);
            LimitSurface.Evaluator eval = limit.evaluator(f, faceLevel[i]);
            double[] uv = new double[2], p = new double[3];
            for (int k = 0; k < n; k++) {
                int v = fv[cornerStart[f] + k], e = refiner.faceEdge(f, k);
                if (vertexOwner[v] == i) {
                    cornerParameters(f, k, uv);
                    evaluate(eval, f, uv[0], uv[1], p);
                    System.arraycopy(p, 0, cornerPoint, 3 * v, 3);
                }
                if (edgeOwner[e] == i) {
                    int r = rate[e];
                    boolean forward = v == ev[2 * e];
                    double[] pts = new double[3 * Math.max(0, r - 1)];
                    for (int c = 1; c < r; c++) {
                        edgeParameters(f, k, c, r, uv);
                        evaluate(eval, f, uv[0], uv[1], p);
                        // Stored in the edge's own direction, so that faces running either way find the same point.
                        int ce = forward ? c : r - c;
                        System.arraycopy(p, 0, pts, 3 * (ce - 1), 3);
                    }
                    edgePoints[e] = pts;
                }
            }
            if (!loop && n != 4) {
                // Spoke k runs from edge k's midpoint (point 0) to the centre (point S_k); its inner points, then the centre.
                FacePattern pattern = quadPattern[i];
                int total = 0;
                for (int k = 0; k < n; k++) total += pattern.spokeRate(k) - 1;
                double[] pts = new double[3 * (total + 1)];
                int o = 0;
                for (int k = 0; k < n; k++) {
                    int s = pattern.spokeRate(k);
                    for (int j = 1; j < s; j++, o += 3) {
                        faceParameters(n, k, 1, (double) j / s, uv);
                        evaluate(eval, f, uv[0], uv[1], p);
                        System.arraycopy(p, 0, pts, o, 3);
                    }
                }
                faceParameters(n, 0, 1, 1, uv);
                evaluate(eval, f, uv[0], uv[1], p);
                System.arraycopy(p, 0, pts, o, 3);
                spokePoints[i] = pts;
            }
            boundPieces(i, eval);
        });
    }

    /**
     * The limit position at face (u, v) into p; where the evaluator has no value there (an end
     * patch it does not handle), the face's control centroid, counted for --stats.
     */
    private boolean evaluate(LimitSurface.Evaluator eval, int f, double u, double v, double[] p) {
        if (eval.evaluate(u, v, p, null, null)) return true;
        unevaluated.incrementAndGet();
        centroid(f, p);
        return false;
    }

    private void centroid(int f, double[] p) {
        int[] fv = control.faceVertices();
        double[] pos = control.positions();
        int n = refiner.faceSize(f);
        p[0] = p[1] = p[2] = 0;
        for (int k = 0; k < n; k++) for (int a = 0; a < 3; a++) p[a] += pos[3 * fv[cornerStart[f] + k] + a] / n;
    }

    /**
     * The shared point that vertex k along edge {@code subEdge} of grid g takes (k in the edge's
     * direction), into p at offset o.
     */
    private void sharedQuadPoint(int g, int subEdge, int k, double[] p, int o) {
        int i = gridFace[g], sub = gridSub[g], f = faces[i];
        FacePattern pattern = quadPattern[i];
        int base = pattern.baseEdge(sub, subEdge);
        if (base >= 0) {
            basePoint(f, base, pattern.basePoint(sub, subEdge, k), p, o);
            return;
        }
        int n = pattern.size(), spoke, j;
        if (subEdge == 1) {
            spoke = sub;
            j = k;
        } else {
            // Edge 2 runs from the centre to edge (sub - 1)'s midpoint: that spoke backwards.
            spoke = (sub + n - 1) % n;
            j = pattern.spokeRate(spoke) - k;
        }
        int s = pattern.spokeRate(spoke);
        if (j == 0) {
            basePoint(f, spoke, pattern.rate(spoke) / 2, p, o);
        } else {
            double[] pts = spokePoints[i];
            int at;
            if (j == s) {
                at = pts.length - 3;
            } else {
                at = 0;
                for (int q = 0; q < spoke; q++) at += 3 * (pattern.spokeRate(q) - 1);
                at += 3 * (j - 1);
            }
            System.arraycopy(pts, at, p, o, 3);
        }
    }

    /** Point c (counted from corner k) of face f's edge k, from the shared tables, into p at o. */
    private void basePoint(int f, int k, int c, double[] p, int o) {
        int e = refiner.faceEdge(f, k), r = rate[e];
        int v = control.faceVertices()[cornerStart[f] + k];
        int[] ev = edgeVertex;
        boolean forward = v == ev[2 * e];
        int ce = forward ? c : r - c;
        if (ce == 0) System.arraycopy(cornerPoint, 3 * ev[2 * e], p, o, 3);
        else if (ce == r) System.arraycopy(cornerPoint, 3 * ev[2 * e + 1], p, o, 3);
        else System.arraycopy(edgePoints[e], 3 * (ce - 1), p, o, 3);
    }

    // ------------------------------------------------------------------ pieces

    /** Boxes of face i's pieces before they are built: the Bezier hull of their range where known, else the face's one-ring hull. */
    private void boundPieces(int i, LimitSurface.Evaluator eval) {
        int f = faces[i], n = refiner.faceSize(f);
        double[] ring = new double[6], box = new double[6], lo = new double[2], hi = new double[2];
        refiner.oneRingBounds(f, ring);
        boolean hull = !loop && eval.isRegular();
        for (int g = firstGrid[i]; g < firstGrid[i + 1]; g++) {
            for (int piece = firstPiece[g]; piece < firstPiece[g + 1]; piece++) {
                double[] b = ring;
                if (hull) {
                    parameterRange(g, piece - firstPiece[g], n, lo, hi);
                    if (eval.bounds(lo[0], hi[0], lo[1], hi[1], box)) b = box;
                }
                BoxList.store(tight, piece, b);
            }
        }
    }

    /** The face-parameter range of the vertices of piece k of grid g (snapped edge vertices may lie past the cells' range). */
    private void parameterRange(int g, int k, int n, double[] lo, double[] hi) {
        GridPattern p = quadPattern[gridFace[g]].subFace(gridSub[g]);
        GridPieces pieces = gridPieces[g];
        int i0 = pieces.i0(k), i1 = pieces.i1(k), j0 = pieces.j0(k), j1 = pieces.j1(k);
        double u0 = Double.POSITIVE_INFINITY, v0 = u0, u1 = Double.NEGATIVE_INFINITY, v1 = u1;
        double[] uv = new double[2];
        // Interior parameters are linear in the indices, so the extremes are on the piece's border.
        for (int i = i0; i <= i1; i++) {
            for (int j = j0; j <= j1; j += (i == i0 || i == i1) ? 1 : Math.max(1, j1 - j0)) {
                faceParameters(n, gridSub[g], p.u(i, j), p.v(i, j), uv);
                u0 = Math.min(u0, uv[0]); u1 = Math.max(u1, uv[0]);
                v0 = Math.min(v0, uv[1]); v1 = Math.max(v1, uv[1]);
            }
        }
        lo[0] = u0; lo[1] = v0; hi[0] = u1; hi[1] = v1;
    }

    /** Heap piece p will hold: an upper bound known before it is built. */
    private long pieceBytes(int p) {
        int g = pieceGrid[p];
        long vertices, tris;
        if (loop) {
            TrianglePattern t = triPattern[gridFace[g]];
            vertices = t.vertexCount();
            tris = t.triangleCount();
            return HeapBudget.sum(HeapBudget.product(vertices, 8L * (smooth ? 6 : 3) + (uvs ? 16 : 0)),
                    HeapBudget.product(tris, AdaptiveTessellation.PATCH_BYTES_PER_TRIANGLE));
        }
        GridPieces pieces = gridPieces[g];
        int k = p - firstPiece[g];
        long nu = pieces.i1(k) - pieces.i0(k) + 1, nv = pieces.j1(k) - pieces.j0(k) + 1;
        vertices = nu * nv;
        tris = 2 * (nu - 1) * (nv - 1);
        // Positions, normals and uvs per vertex; the grid's nodes (288 bytes per eight leaves of about four cells); headers.
        return vertices * (12 + (smooth ? 12 : 0) + (uvs ? 8 : 0)) + tris * 5 + 512;
    }

    /** Every piece, face by face on all cores (one evaluator per face). */
    private void buildAll(TessellationPiece[] out) {
        IntStream.range(0, faces.length).parallel().forEach(i -> {
            LimitSurface.Evaluator eval = limit.evaluator(faces[i], faceLevel[i]);
            LimitSurface.UvEvaluator uv = uvs ? limit.uvEvaluator(faces[i], faceLevel[i]) : null;
            for (int g = firstGrid[i]; g < firstGrid[i + 1]; g++) {
                for (int p = firstPiece[g]; p < firstPiece[g + 1]; p++) out[p] = buildPiece(p, eval, uv);
            }
        });
    }

    /** The combined method: the cheapest pieces built and pinned while the eager budget lasts. */
    private void pinWithinBudget(BuildShared shared) {
        pinned = new TessellationPiece[pieceCount];
        long[] cost = new long[pieceCount];
        for (int p = 0; p < pieceCount; p++) cost[p] = pieceBytes(p);
        int[] chosen = shared.takeCheapest(cost);
        int take = chosen.length;
        Arrays.sort(chosen);
        IntStream.range(0, take).parallel().forEach(k -> pinned[chosen[k]] = (TessellationPiece) build(chosen[k]));
        for (int k = 0; k < take; k++) pinnedBytes += pinned[chosen[k]].bytes();
        pinnedCount = take;
    }

    /** Builds piece {@code p} (the cache calls this on a miss). */
    @Override
    public CachedPatch build(int p) {
        int i = gridFace[pieceGrid[p]];
        LimitSurface.Evaluator eval = limit.evaluator(faces[i], faceLevel[i]);
        LimitSurface.UvEvaluator uv = uvs ? limit.uvEvaluator(faces[i], faceLevel[i]) : null;
        return buildPiece(p, eval, uv);
    }

    private TessellationPiece buildPiece(int p, LimitSurface.Evaluator eval, LimitSurface.UvEvaluator uvEval) {
        TessellationPiece piece = loop ? buildTriangles(p, eval, uvEval) : buildGrid(p, eval, uvEval);
        double[] box = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        piece.include(box);
        // The piece's own box, tighter than the estimate, turns rays away before the cache is asked, even after eviction.
        if (box[0] <= box[3]) BoxList.store(tight, p, box);
        return piece;
    }

    /** Scratch of one vertex's evaluation. */
    private static final class VertexScratch {
        final double[] uv = new double[2], p = new double[3], du = new double[3], dv = new double[3], t = new double[2];
    }

    private GridPiece buildGrid(int p, LimitSurface.Evaluator eval, LimitSurface.UvEvaluator uvEval) {
        int g = pieceGrid[p], i = gridFace[g], sub = gridSub[g], f = faces[i], n = refiner.faceSize(f);
        GridPattern pattern = quadPattern[i].subFace(sub);
        GridPieces pieces = gridPieces[g];
        int k = p - firstPiece[g];
        int i0 = pieces.i0(k), i1 = pieces.i1(k), j0 = pieces.j0(k), j1 = pieces.j1(k);
        int nu = i1 - i0 + 1, nv = j1 - j0 + 1, ru = pattern.columns(), rv = pattern.rows();
        float[] xyz = new float[3 * nu * nv];
        float[] normals = smooth ? new float[3 * nu * nv] : null, tex = uvEval != null ? new float[2 * nu * nv] : null;
        VertexScratch s = new VertexScratch();
        for (int j = j0; j <= j1; j++) {
            for (int ii = i0; ii <= i1; ii++) {
                int w = (j - j0) * nu + (ii - i0);
                faceParameters(n, sub, pattern.u(ii, j), pattern.v(ii, j), s.uv);
                boolean border = j == 0 || ii == ru || j == rv || ii == 0;
                if (border) {
                    if (j == 0) sharedQuadPoint(g, 0, ii, s.p, 0);
                    else if (ii == ru) sharedQuadPoint(g, 1, j, s.p, 0);
                    else if (j == rv) sharedQuadPoint(g, 2, ru - ii, s.p, 0);
                    else sharedQuadPoint(g, 3, rv - j, s.p, 0);
                    for (int a = 0; a < 3; a++) xyz[3 * w + a] = (float) s.p[a];
                }
                if (!border || normals != null) {
                    // Flat shading needs no derivatives: positions alone cost a third as much.
                    if (!eval.evaluate(s.uv[0], s.uv[1], s.p, normals != null ? s.du : null, normals != null ? s.dv : null)) {
                        unevaluated.incrementAndGet();
                        centroid(f, s.p);
                        s.du[0] = s.du[1] = s.du[2] = s.dv[0] = s.dv[1] = s.dv[2] = 0;
                    }
                    if (!border) for (int a = 0; a < 3; a++) xyz[3 * w + a] = (float) s.p[a];
                    if (normals != null) normal(s.du, s.dv, normals, 3 * w);
                }
                if (tex != null) {
                    uvEval.evaluate(s.uv[0], s.uv[1], s.t);
                    tex[2 * w] = (float) s.t[0];
                    tex[2 * w + 1] = (float) s.t[1];
                }
            }
        }
        GridPatch grid = new GridPatch(nu, nv, xyz, normals, null, 0, 0, 1, 1, GridPatch.DEFAULT_LEAF_SIZE);
        return new GridPiece(grid, xyz, normals, tex);
    }

    /** The unit normal du x dv into out at o (zero where the derivatives are degenerate: then the facet's normal shades). */
    private static void normal(double[] du, double[] dv, float[] out, int o) {
        double x = du[1] * dv[2] - du[2] * dv[1], y = du[2] * dv[0] - du[0] * dv[2], z = du[0] * dv[1] - du[1] * dv[0];
        double len = Math.sqrt(x * x + y * y + z * z);
        if (!(len > 0) || !Double.isFinite(len)) {
            out[o] = out[o + 1] = out[o + 2] = 0;
            return;
        }
        out[o] = (float) (x / len);
        out[o + 1] = (float) (y / len);
        out[o + 2] = (float) (z / len);
    }

    /** A Loop face's triangular grid as one piece of triangles. */
    private PatchTriangles buildTriangles(int p, LimitSurface.Evaluator eval, LimitSurface.UvEvaluator uvEval) {
        int i = gridFace[pieceGrid[p]], f = faces[i];
        TrianglePattern t = triPattern[i];
        int r = t.rate(), nvtx = t.vertexCount();
        double[] pos = new double[3 * nvtx], nrm = smooth ? new double[3 * nvtx] : null, tex = uvEval != null ? new double[2 * nvtx] : null;
        VertexScratch s = new VertexScratch();
        float[] fn = new float[3];
        for (int j = 0; j <= r; j++) {
            for (int ii = 0; ii + j <= r; ii++) {
                int w = t.vertex(ii, j);
                s.uv[0] = t.u(ii, j);
                s.uv[1] = t.v(ii, j);
                boolean border = j == 0 || ii + j == r || ii == 0;
                if (border) {
                    if (j == 0) basePoint(f, 0, t.edgePoint(0, ii), pos, 3 * w);
                    else if (ii + j == r) basePoint(f, 1, t.edgePoint(1, j), pos, 3 * w);
                    else basePoint(f, 2, t.edgePoint(2, r - j), pos, 3 * w);
                }
                if (!border || nrm != null) {
                    if (!eval.evaluate(s.uv[0], s.uv[1], s.p, s.du, s.dv)) {
                        unevaluated.incrementAndGet();
                        centroid(f, s.p);
                        s.du[0] = s.du[1] = s.du[2] = s.dv[0] = s.dv[1] = s.dv[2] = 0;
                    }
                    if (!border) System.arraycopy(s.p, 0, pos, 3 * w, 3);
                    if (nrm != null) {
                        normal(s.du, s.dv, fn, 0);
                        for (int a = 0; a < 3; a++) nrm[3 * w + a] = fn[a];
                    }
                }
                if (tex != null) {
                    uvEval.evaluate(s.uv[0], s.uv[1], s.t);
                    tex[2 * w] = s.t[0];
                    tex[2 * w + 1] = s.t[1];
                }
            }
        }
        // The triangle pattern's vertices and triangles as a mesh; its positions are rounded to float, as the grids' are.
        for (int a = 0; a < pos.length; a++) pos[a] = (float) pos[a];
        int nt = t.triangleCount();
        int[] sizes = new int[nt], vi = new int[3 * nt];
        Arrays.fill(sizes, 3);
        int[] tri = new int[3];
        for (int q = 0; q < nt; q++) {
            t.triangle(q, tri);
            System.arraycopy(tri, 0, vi, 3 * q, 3);
        }
        MeshData d = new MeshData(pos, nrm, tex, sizes, vi, nrm != null ? vi : null, tex != null ? vi : null, control.source(), null, null);
        return new PatchTriangles(p, d, kind);
    }

    // ------------------------------------------------------------------ queries (object space)

    private TessellationPiece piece(int p, RecentPatches recent) {
        TessellationPiece q = pinned != null ? pinned[p] : null;
        return q != null ? q : (TessellationPiece) cache.get(table, p, this, recent);
    }

    @Override
    public boolean intersect(Ray ray, Hit hit, TraceContext ctx) { return top.intersect(ray, hit, ctx); }

    @Override
    public boolean occluded(Ray ray, TraceContext ctx) { return top.occluded(ray, ctx); }

    @Override
    public void spans(Ray ray, SpanBuffer out, TraceContext ctx, GObject owner) {
        TriangleSpans.spans(top, crossingVisitor, owner, ray, out, ctx);
    }

    private void visitPiece(int p, Ray ray, TraversalScratch s) {
        TraceContext ctx = (TraceContext) s;
        piece(p, ctx.recentPatches).addCrossings(p, ray, ctx);
    }

    @Override
    public void shade(double x, double y, double z, Hit hit, ShadingData sd) {
        piece(hit.prim, sd.recentPatches).shade(smooth, hit.sub, hit.u, hit.v, sd);
    }

    @Override
    public int faceGroup(int prim, int sub) {
        int[] groups = control.faceGroups();
        return groups == null ? -1 : groups[faces[gridFace[pieceGrid[prim]]]];
    }

    // ---- PrimitiveSet: the pieces ----

    @Override public int size() { return pieceCount; }

    @Override
    public void bounds(int p, double[] out) {
        for (int k = 0; k < 6; k++) out[k] = Float.intBitsToFloat(tight[6 * p + k]);
    }

    @Override
    public boolean intersect(int p, Ray ray, PrimitiveHit hit, TraversalScratch s) {
        if (!BoxList.crosses(tight, p, ray, s)) return false;
        TraceContext ctx = (TraceContext) s;
        if (!piece(p, ctx.recentPatches).intersect(ray, hit, ctx)) return false;
        hit.prim = p;
        return true;
    }

    @Override
    public boolean occluded(int p, Ray ray, TraversalScratch s) {
        if (!BoxList.crosses(tight, p, ray, s)) return false;
        TraceContext ctx = (TraceContext) s;
        return piece(p, ctx.recentPatches).occluded(ray, ctx);
    }

    // ------------------------------------------------------------------ whole mesh and statistics

    @Override
    public MeshData welded() {
        long need = 0;
        for (int p = 0; p < pieceCount; p++) need = HeapBudget.sum(need, pieceBytes(p));
        HeapBudget.require(HeapBudget.product(need, 8), "the tessellation of " + name);
        TessellationPiece[] all = new TessellationPiece[pieceCount];
        buildAll(all);
        MeshData[] parts = new MeshData[pieceCount];
        int[] groups = control.faceGroups() == null ? null : new int[pieceCount];
        for (int p = 0; p < pieceCount; p++) {
            parts[p] = meshOf(all[p]);
            if (groups != null) groups[p] = control.faceGroups()[faces[gridFace[pieceGrid[p]]]];
        }
        return AdaptiveTessellation.weld(AdaptiveTessellation.join(parts, control.source(), groups, control.groupNames()));
    }

    /** A piece's triangles as a mesh (positions, and per-vertex normals and uvs where it has them). */
    private static MeshData meshOf(TessellationPiece piece) {
        if (piece instanceof PatchTriangles t) {
            int n = t.triangleCount;
            int[] sizes = new int[n];
            Arrays.fill(sizes, 3);
            return new MeshData(t.pos, t.normals, t.uvs, sizes, t.tri, t.triNormal, t.triUv, null, null, null);
        }
        return ((GridPiece) piece).mesh();
    }

    @Override
    public long triangleCount() { return triangles; }

    @Override
    public int[] edgeLevels() {
        int[] l = new int[rate.length];
        for (int e = 0; e < l.length; e++) l[e] = LimitSurface.levelForRate(rate[e]);
        return l;
    }

    /** The rate chosen for each control edge (indexed as the refiner numbers edges). */
    int[] edgeRates() { return rate.clone(); }

    @Override
    public String statistics() {
        if (rate == null) return "subdiv " + name + ": " + method.word() + ", not tessellated (the scene was not built)";
        int min = Integer.MAX_VALUE, max = 0;
        int[] sorted = rate.clone();
        Arrays.sort(sorted);
        if (sorted.length > 0) {
            min = sorted[0];
            max = sorted[sorted.length - 1];
        }
        String rates = sorted.length == 0 ? "none" : min == max ? Integer.toString(min)
                : String.format(Locale.ROOT, "%d-%d (median %d)", min, max, sorted[sorted.length / 2]);
        String head = String.format(Locale.ROOT, "subdiv %s: %s%s, %d faces, edge rates %s, %,d triangles (%,d of no area), %d pieces",
                name, method.word(), used != method ? " (as combined: the eager tessellation does not fit)" : "", faces == null ? 0 : faces.length,
                rates, triangles, zeroArea, pieceCount);
        long bad = unevaluated.get();
        if (bad > 0) head += String.format(Locale.ROOT, " (%d points without a limit value, placed at their face's centroid)", bad);
        if (used == AdaptiveSubdivisionSurface.Method.PROJECTED) return head + String.format(Locale.ROOT, "; eager %s", HeapBudget.format(pinnedBytes));
        String pin = used == AdaptiveSubdivisionSurface.Method.COMBINED ? String.format(Locale.ROOT, "; %d pieces eager (%s)", pinnedCount, HeapBudget.format(pinnedBytes)) : "";
        return head + pin + "; " + (table == null ? "no pieces cached" : table.stats().summary());
    }
}
