package lt.spindulys.scene;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.stream.IntStream;

import lt.spindulys.accel.Accelerator;
import lt.spindulys.accel.BoxList;
import lt.spindulys.accel.PrimitiveHit;
import lt.spindulys.accel.PrimitiveSet;
import lt.spindulys.accel.PrimitiveVisitor;
import lt.spindulys.accel.TraversalScratch;
import lt.spindulys.adaptive.CachedPatch;
import lt.spindulys.adaptive.EdgeLevels;
import lt.spindulys.adaptive.PatchCache;
import lt.spindulys.adaptive.PatchSource;
import lt.spindulys.adaptive.RecentPatches;
import lt.spindulys.limits.HeapBudget;
import lt.spindulys.math.Placement;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.PatchRefiner;
import lt.spindulys.subdiv.SubdivOptions;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;
import lt.spindulys.trace.TraceContext;

/**
 * The tessellation of one adaptive subdivision surface in one scene build, shared by every
 * instance of it: the level of each control edge (from the view, the largest any placement
 * needs, or fixed), and the triangles, either eager (one {@link TriangleMesh} of every patch) or
 * lazy (a structure over the coarse faces, each refined when a ray first reaches it and kept in
 * the scene's {@link PatchCache}), or a mix of the two (the combined method: patches pinned while
 * the eager budget lasts, the rest lazy).
 *
 * <p>Every patch is a pure function of its face, its level and its edges' levels, so the image
 * does not depend on which patches were cached, evicted and rebuilt, on the cache's size or on
 * the number of threads. A face's box is the box of its one-ring control points, which contains
 * every refined level of it (the weights of every scheme's rules, Catmull-Clark's, Loop's and
 * bilinear's, are non-negative: {@link PatchRefiner#oneRingBounds}): no ray can miss a part of
 * the surface that bulges past the coarse mesh.
 */
final class AdaptiveTessellation implements SurfaceTessellation, PrimitiveSet, PatchSource {
    /** Off-screen edges are refined as if this many times shorter (Cycles' offscreen dicing scale). */
    static final double OFFSCREEN_SCALE = 4;

    private final AdaptiveSubdivisionSurface.Geometry geometry;
    private final PatchRefiner refiner;
    /** Whether the faces split into triangles (Loop) rather than quads. */
    private final boolean loop;
    private final AdaptiveSubdivisionSurface.Method method;
    private final boolean smooth;
    private final int fixedLevel, maxLevel;
    private final double target;
    private final AdaptiveSubdivisionSurface.Levels levels;
    private final String name;
    private final List<Placement> placements = new ArrayList<>();

    // ---- made by finish ----
    private AdaptiveSubdivisionSurface.Method used;
    private int[] edgeLevel, faceLevel;
    /** Non-hole faces: the top structure's primitives. */
    private int[] faces;
    /**
     * Each face's box as float bits: its one-ring box until its patch is first built, then the
     * patch's own (tighter) box, so that a ray that misses a built patch is turned away before the
     * cache is asked for it, even after the patch was evicted.
     */
    private int[] tight;
    private AcceleratorKind kind;
    private TriangleMesh mesh;
    private Accelerator top;
    private PatchCache cache;
    private PatchCache.Table table;
    private PatchTriangles[] pinned;
    private long pinnedBytes, eagerBytes;
    private int pinnedCount;
    private final PrimitiveVisitor crossingVisitor = this::visitPatch;

    AdaptiveTessellation(AdaptiveSubdivisionSurface s, double target) {
        geometry = s.geometry();
        refiner = geometry.refiner();
        loop = refiner.control().options().scheme() == SubdivOptions.Scheme.LOOP;
        method = s.method();
        smooth = s.isSmooth();
        fixedLevel = s.fixedLevel();
        maxLevel = s.maxLevel();
        levels = s.levels();
        this.target = target;
        name = displayName(s);
    }

    /** The surface's name in --stats: an unnamed surface is known by its control mesh's file. */
    static String displayName(AdaptiveSubdivisionSurface s) {
        String source = s.control().source();
        return s.name().equals(s.kind()) && source != null ? source.substring(Math.max(source.lastIndexOf('/'), source.lastIndexOf('\\')) + 1) : s.name();
    }

    /**
     * Heap a flat eager mesh needs per triangle at its peak, beyond the patches it is made from:
     * its index arrays (positions, normals, uvs: 36 bytes), the joined vertex data (about 40), the
     * structure (about 30) and the structure's build (bounds and order, about 60), with a margin.
     */
    static final long FLAT_BYTES_PER_TRIANGLE = 200;

    /**
     * Heap a lazy patch holds per triangle beyond {@link PatchRefiner#patchBytes}: the triangle,
     * normal and uv index arrays (36 bytes) and its structure (about 30), with a margin.
     */
    static final long PATCH_BYTES_PER_TRIANGLE = 80;

    /**
     * Triangles of face {@code f}'s patch: a polygon's fan at level 0, else two per quad (n quads
     * at level 1), or for Loop the triangle's own 4^l.
     */
    private long triangles(int f) {
        int n = refiner.faceSize(f), l = faceLevel[f];
        if (l == 0) return n - 2;
        return loop ? 1L << (2 * l) : 2L * n << (2 * (l - 1));
    }

    /** Heap face {@code f}'s patch holds, all told (what pinning it costs). */
    private long patchCost(int f) {
        return HeapBudget.sum(refiner.patchBytes(f, faceLevel[f], smooth), HeapBudget.product(triangles(f), PATCH_BYTES_PER_TRIANGLE));
    }

    /** Records one placement (object to world over the shutter) of a surface using this tessellation. */
    @Override
    public synchronized void addPlacement(Placement p, boolean backHidden) { placements.add(p); }

    /** True if some patch is refined on demand (not eager, not all pinned). */
    @Override
    public boolean refinesWhileTracing() { return top != null && pinnedCount < faces.length; }

    /** Chooses the levels and builds the eager part; called once, after every placement is known. */
    @Override
    public void finish(BuildShared shared, BuildContext root) {
        kind = root.accelerator();
        chooseLevels(shared);
        int nf = refiner.faceCount();
        int count = 0;
        for (int f = 0; f < nf; f++) if (!refiner.isHole(f)) count++;
        faces = new int[count];
        for (int f = 0, k = 0; f < nf; f++) if (!refiner.isHole(f)) faces[k++] = f;
        used = method;
        if (method == AdaptiveSubdivisionSurface.Method.PROJECTED) {
            long patches = 0, triangles = 0;
            for (int f : faces) {
                patches = HeapBudget.sum(patches, refiner.patchBytes(f, faceLevel[f], smooth));
                triangles = HeapBudget.sum(triangles, triangles(f));
            }
            // The patches are held while the flat mesh is made from them; the mesh then holds its
            // own arrays, and its structure's build its temporary ones.
            long need = HeapBudget.sum(patches, HeapBudget.product(triangles, FLAT_BYTES_PER_TRIANGLE));
            if (HeapBudget.fits(need) && shared.takeEager(need)) {
                buildEager(root);
                eagerBytes = need;
                return;
            }
            // Does not fit: refine lazily instead, as the combined method does, within the budget.
            used = AdaptiveSubdivisionSurface.Method.COMBINED;
        }
        cache = shared.cache();
        table = cache.table(faces.length, name);
        tight = new int[6 * faces.length];
        double[] box = new double[6];
        for (int i = 0; i < faces.length; i++) {
            refiner.oneRingBounds(faces[i], box);
            BoxList.store(tight, i, box);
        }
        if (used == AdaptiveSubdivisionSurface.Method.COMBINED) pinWithinBudget(shared);
        top = kind.build(this);
    }

    private void chooseLevels(BuildShared shared) {
        int[] ev = refiner.edgeVertices();
        int ne = refiner.edgeCount();
        edgeLevel = new int[ne];
        if (fixedLevel >= 0) {
            Arrays.fill(edgeLevel, fixedLevel);
        } else if (levels == AdaptiveSubdivisionSurface.Levels.OBJECT) {
            int l = 0;
            for (Placement p : placements) {
                l = Math.max(l, EdgeLevels.perObject(shared.view(), refiner.control().positions(), ev, p, target, maxLevel, OFFSCREEN_SCALE));
            }
            Arrays.fill(edgeLevel, l);
        } else {
            for (Placement p : placements) {
                EdgeLevels.perEdgeMax(shared.view(), refiner.control().positions(), ev, p, target, maxLevel, OFFSCREEN_SCALE, edgeLevel);
            }
        }
        int nf = refiner.faceCount();
        faceLevel = new int[nf];
        for (int f = 0; f < nf; f++) {
            int l = 0;
            for (int k = 0, n = refiner.faceSize(f); k < n; k++) l = Math.max(l, edgeLevel[refiner.faceEdge(f, k)]);
            faceLevel[f] = l;
        }
    }

    /** Levels of the face's edges, corner by corner. */
    private int[] edgeLevels(int f) {
        int n = refiner.faceSize(f);
        int[] e = new int[n];
        for (int k = 0; k < n; k++) e[k] = edgeLevel[refiner.faceEdge(f, k)];
        return e;
    }

    /**
     * The patch of face {@code f}: refined to its level, each edge's vertices placed at the edge's
     * level, and each corner at the least level of the control edges around its vertex, which
     * every face around the vertex computes alike (so no crack opens where several faces meet).
     */
    private MeshData refine(int f) {
        int n = refiner.faceSize(f);
        int[] corners = new int[n];
        for (int k = 0; k < n; k++) corners[k] = refiner.vertexLevel(f, k, edgeLevel);
        return refiner.refine(f, faceLevel[f], edgeLevels(f), corners, smooth);
    }

    /** Every patch built (on all cores: each is independent) and joined into one flat mesh. */
    private void buildEager(BuildContext root) {
        MeshData[] parts = new MeshData[faces.length];
        IntStream.range(0, faces.length).parallel().forEach(i -> parts[i] = refine(faces[i]));
        MeshData joined = join(parts, refiner.control().source(), faceGroups(), refiner.control().groupNames());
        mesh = new TriangleMesh(joined);
        mesh.smooth(smooth);
        mesh.freeze(root.within(Placement.of(Transform.IDENTITY, root.shutterOpen(), root.shutterClose()), null), 0);
    }

    /** The control face group of each part (patch of {@link #faces}), or null when the control mesh has no groups. */
    private int[] faceGroups() {
        int[] control = refiner.control().faceGroups();
        if (control == null) return null;
        int[] out = new int[faces.length];
        for (int i = 0; i < faces.length; i++) out[i] = control[faces[i]];
        return out;
    }

    /**
     * The face group of a hit's primitive: the eager mesh's triangle's, or the control face's of
     * the lazy structure's primitive (a coarse face, whose every triangle is in its group).
     */
    @Override
    public int faceGroup(int prim, int sub) {
        if (mesh != null) return mesh.faceGroup(prim, sub);
        int[] control = refiner.control().faceGroups();
        return control == null ? -1 : control[faces[prim]];
    }

    /**
     * One mesh of the parts, in face order: their vertices side by side (the census welds equal
     * positions); each part's faces in its group of {@code partGroups} (named by
     * {@code groupNames}), when given.
     */
    static MeshData join(MeshData[] parts, String source, int[] partGroups, String[] groupNames) {
        long nv = 0, nn = 0, nu = 0, nfaces = 0, nc = 0;
        boolean normals = false, uvs = false;
        for (MeshData d : parts) {
            nv += d.positions().length;
            if (d.normals() != null) { nn += d.normals().length; normals = true; }
            if (d.uvs() != null) { nu += d.uvs().length; uvs = true; }
            nfaces += d.faceSizes().length;
            nc += d.vertexIndex().length;
        }
        if (nv > Integer.MAX_VALUE - 8 || nc > Integer.MAX_VALUE - 8) throw new IllegalArgumentException("the tessellation is too large for one mesh");
        double[] p = new double[(int) nv], n = normals ? new double[(int) nn] : null, t = uvs ? new double[(int) nu] : null;
        int[] sizes = new int[(int) nfaces], vi = new int[(int) nc], ni = normals ? new int[(int) nc] : null, ti = uvs ? new int[(int) nc] : null;
        int[] groups = partGroups != null ? new int[(int) nfaces] : null;
        int op = 0, on = 0, ot = 0, of = 0, oc = 0, part = 0;
        for (MeshData d : parts) {
            if (groups != null) Arrays.fill(groups, of, of + d.faceSizes().length, partGroups[part]);
            part++;
            int vBase = op / 3, nBase = on / 3, tBase = ot / 2;
            System.arraycopy(d.positions(), 0, p, op, d.positions().length);
            op += d.positions().length;
            if (d.normals() != null) { System.arraycopy(d.normals(), 0, n, on, d.normals().length); on += d.normals().length; }
            if (d.uvs() != null) { System.arraycopy(d.uvs(), 0, t, ot, d.uvs().length); ot += d.uvs().length; }
            System.arraycopy(d.faceSizes(), 0, sizes, of, d.faceSizes().length);
            of += d.faceSizes().length;
            int[] dv = d.vertexIndex(), dn = d.normalIndex(), dt = d.uvIndex();
            for (int c = 0; c < dv.length; c++) {
                vi[oc + c] = dv[c] + vBase;
                if (ni != null) ni[oc + c] = dn == null ? -1 : dn[c] + nBase;
                if (ti != null) ti[oc + c] = dt == null ? -1 : dt[c] + tBase;
            }
            oc += dv.length;
        }
        return new MeshData(p, n, t, sizes, vi, ni, ti, source, groups, groups != null ? groupNames : null);
    }

    /**
     * The whole tessellation as one welded mesh, as {@code render subdivide --scene} writes it:
     * every patch at its chosen levels, vertices at the same position joined into one (the
     * stitching makes shared edge vertices bit-identical, so the welded mesh has no crack), and
     * triangles that the stitching collapsed dropped.
     */
    @Override
    public MeshData welded() {
        long need = 0;
        for (int f : faces) need = HeapBudget.sum(need, refiner.patchBytes(f, faceLevel[f], smooth));
        HeapBudget.require(HeapBudget.product(need, 3), "the tessellation of " + name);
        MeshData[] parts = new MeshData[faces.length];
        IntStream.range(0, faces.length).parallel().forEach(i -> parts[i] = refine(faces[i]));
        return weld(join(parts, refiner.control().source(), faceGroups(), refiner.control().groupNames()));
    }

    /** {@code d} with vertices at equal positions joined and the triangles that collapse dropped. */
    static MeshData weld(MeshData d) {
        double[] p = d.positions();
        int n = p.length / 3;
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) order[i] = i;
        Arrays.sort(order, (a, b) -> {
            for (int k = 0; k < 3; k++) {
                int c = Double.compare(p[3 * a + k], p[3 * b + k]);
                if (c != 0) return c;
            }
            return Integer.compare(a, b);
        });
        int[] map = new int[n];
        double[] q = new double[p.length];
        int m = -1;
        for (int k = 0; k < n; k++) {
            int i = order[k];
            if (m < 0 || p[3 * i] != q[3 * m] || p[3 * i + 1] != q[3 * m + 1] || p[3 * i + 2] != q[3 * m + 2]) {
                m++;
                System.arraycopy(p, 3 * i, q, 3 * m, 3);
            }
            map[i] = m;
        }
        int[] sizes = d.faceSizes(), vi = d.vertexIndex(), ni = d.normalIndex(), ti = d.uvIndex();
        int faces = 0, corners = 0;
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            if (collapsed(map, vi, c, sizes[f])) continue;
            faces++;
            corners += sizes[f];
        }
        int[] os = new int[faces], ov = new int[corners], on = ni != null ? new int[corners] : null, ot = ti != null ? new int[corners] : null;
        int[] fg = d.faceGroups(), og = fg != null ? new int[faces] : null;
        for (int f = 0, c = 0, of = 0, oc = 0; f < sizes.length; c += sizes[f], f++) {
            if (collapsed(map, vi, c, sizes[f])) continue;
            if (og != null) og[of] = fg[f];
            os[of++] = sizes[f];
            for (int j = 0; j < sizes[f]; j++, oc++) {
                ov[oc] = map[vi[c + j]];
                if (on != null) on[oc] = ni[c + j];
                if (ot != null) ot[oc] = ti[c + j];
            }
        }
        return new MeshData(Arrays.copyOf(q, 3 * (m + 1)), d.normals(), d.uvs(), os, ov, on, ot, d.source(), og, og != null ? d.groupNames() : null);
    }

    /** True if two corners of the face starting at corner {@code c} became one vertex. */
    private static boolean collapsed(int[] map, int[] vi, int c, int size) {
        for (int a = 0; a < size; a++) for (int b = a + 1; b < size; b++) if (map[vi[c + a]] == map[vi[c + b]]) return true;
        return false;
    }

    @Override
    public long triangleCount() {
        long t = 0;
        if (faceLevel != null) for (int f : faces) t = HeapBudget.sum(t, triangles(f));
        return t;
    }

    /** The level chosen for each control edge (indexed as the refiner numbers edges). */
    @Override
    public int[] edgeLevels() { return edgeLevel.clone(); }

    /** The combined method: the cheapest patches built and pinned while the eager budget lasts. */
    private void pinWithinBudget(BuildShared shared) {
        pinned = new PatchTriangles[faces.length];
        long[] cost = new long[faces.length];
        for (int i = 0; i < faces.length; i++) cost[i] = patchCost(faces[i]);
        int[] chosen = shared.takeCheapest(cost);
        int take = chosen.length;
        IntStream.range(0, take).parallel().forEach(k -> {
            int i = chosen[k];
            PatchTriangles p = (PatchTriangles) build(i);
            pinned[i] = p;
        });
        // Built before the structure over the faces, so that it takes their own (tighter) boxes.
        for (int k = 0; k < take; k++) pinnedBytes += pinned[chosen[k]].bytes();
        pinnedCount = take;
    }

    // ---- queries (object space) ----

    @Override
    public boolean intersect(Ray ray, Hit hit, TraceContext ctx) {
        return mesh != null ? mesh.intersectLocal(ray, hit, ctx) : top.intersect(ray, hit, ctx);
    }

    @Override
    public boolean occluded(Ray ray, TraceContext ctx) {
        return mesh != null ? mesh.occluded(ray, ctx) : top.occluded(ray, ctx);
    }

    @Override
    public void spans(Ray ray, SpanBuffer out, TraceContext ctx, GObject owner) {
        if (mesh != null) {
            int first = out.size();
            mesh.spansLocal(ray, out, ctx);
            out.relabel(first, owner);
        } else {
            TriangleSpans.spans(top, crossingVisitor, owner, ray, out, ctx);
        }
    }

    @Override
    public void shade(double x, double y, double z, Hit hit, ShadingData sd) {
        if (mesh != null) mesh.shadeLocal(x, y, z, hit, sd);
        else patch(hit.prim, sd.recentPatches).shade(smooth, hit.sub, hit.u, hit.v, sd);
    }

    private void visitPatch(int i, Ray ray, TraversalScratch s) {
        TraceContext ctx = (TraceContext) s;
        PatchTriangles p = patch(i, ctx.recentPatches);
        p.accel.visit(ray, ctx, p.crossingCollector);
    }

    private PatchTriangles patch(int i, RecentPatches recent) {
        PatchTriangles p = pinned != null ? pinned[i] : null;
        return p != null ? p : (PatchTriangles) cache.get(table, i, this, recent);
    }

    /** Builds the patch of primitive {@code i} (the cache calls this on a miss). */
    @Override
    public CachedPatch build(int i) {
        int f = faces[i];
        PatchTriangles p = new PatchTriangles(i, refine(f), kind);
        if (table != null) table.stats().recordLevel(faceLevel[f]);
        double[] box = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        p.include(box);
        if (box[0] <= box[3]) BoxList.store(tight, i, box);
        return p;
    }

    // ---- PrimitiveSet: the coarse faces ----

    @Override public int size() { return faces.length; }

    @Override
    public void bounds(int i, double[] out) {
        for (int k = 0; k < 6; k++) out[k] = Float.intBitsToFloat(tight[6 * i + k]);
    }

    @Override
    public boolean intersect(int i, Ray ray, PrimitiveHit hit, TraversalScratch s) {
        if (!BoxList.crosses(tight, i, ray, s)) return false;
        TraceContext ctx = (TraceContext) s;
        PatchTriangles p = patch(i, ctx.recentPatches);
        if (!p.accel.intersect(ray, hit, ctx)) return false;
        hit.sub = hit.prim;
        hit.prim = i;
        return true;
    }

    @Override
    public boolean occluded(int i, Ray ray, TraversalScratch s) {
        if (!BoxList.crosses(tight, i, ray, s)) return false;
        TraceContext ctx = (TraceContext) s;
        return patch(i, ctx.recentPatches).accel.occluded(ray, ctx);
    }

    // ---- statistics ----

    /** One line: name, method, faces, levels, eager or pinned bytes, and the cache's counters for this surface. */
    @Override
    public String statistics() {
        int[] hist = new int[maxLevel + 1];
        if (faceLevel != null) for (int f : faces) hist[Math.min(faceLevel[f], maxLevel)]++;
        StringBuilder h = new StringBuilder();
        for (int l = 0; l < hist.length; l++) if (hist[l] > 0) h.append(h.length() == 0 ? "" : " ").append(l).append(':').append(hist[l]);
        String head = String.format(Locale.ROOT, "subdiv %s: %s%s, %d faces, face levels %s", name, method.word(),
                used != method ? " (as combined: the eager tessellation does not fit)" : "", faces == null ? 0 : faces.length, h);
        if (mesh != null) return head + String.format(Locale.ROOT, "; eager %d triangles, %s", mesh.triangleCount(), HeapBudget.format(eagerBytes));
        String pin = used == AdaptiveSubdivisionSurface.Method.COMBINED ? String.format(Locale.ROOT, "; %d patches eager (%s)", pinnedCount, HeapBudget.format(pinnedBytes)) : "";
        return head + pin + "; " + (table == null ? "no patches" : table.stats().summary());
    }
}
