package lt.spindulys.scene;

import lt.spindulys.material.Material;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;

import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;

import lt.spindulys.limits.MessageText;
import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Motion;
import lt.spindulys.math.Placement;
import lt.spindulys.math.Transform;

/**
 * Constructive solid geometry node (the thesis's name): the union, intersection or difference
 * of closed operands (spheres, boxes, cylinders, closed meshes and subdivision surfaces, half
 * spaces, other {@code Bool}s), each with its own transform and material, nested up to
 * {@link #MAX_NESTING} levels.
 *
 * <p><b>How a ray is answered.</b> Each operand reports the spans the ray spends inside it
 * ({@link GObject#spans}); the spans are merged by ray parameter and the operation decides, at
 * every endpoint, whether the ray is inside the result. Where that changes the result has a
 * boundary, named by the operand endpoint that caused the change, so the hit is a leaf surface:
 * {@code hit.object} is the leaf (it shades with its own transform, normals and uv) and
 * {@code hit.flipNormal} is set where a subtracted operand's surface bounds the result, so its
 * outward normal points out of the result. The nearest hit is the first boundary in
 * (tMin, tMax). A Bool reports its own spans in the same way, which is what lets Bools nest.
 * Everything per ray lives in the caller's {@link TraceContext} (pooled span buffers, the
 * traversal stack for the merge cursors): no allocation, no shared mutable state.
 *
 * <p><b>Coincident surfaces.</b> Operand endpoints closer together along the ray than a tie
 * tolerance (a distance of {@link #TIE} times 1 + the largest origin coordinate + the distance
 * travelled, so it scales with the rounding error of the positions involved) are one event: all of them are applied before the result's inside state is compared with the state
 * before the event, so zero-thickness slivers never appear and the outcome does not depend on
 * rounding in which operand's surface comes first. Hence: a union of solids touching along a face
 * has no inner face there; a difference removes a face that a subtracted operand shares with the
 * first (a box minus a box flush with one of its faces is open on that face); an intersection of
 * solids that only touch is empty, and an intersection keeps a face two operands share. Where the
 * state does change at an event, the boundary is named by the first endpoint, in operand order,
 * that moves the result the same way (an entry of a kept operand or an exit of a subtracted one
 * for an entry into the result, the reverse for an exit), so a shared face shows the surface of
 * the earliest operand. The tolerance also swallows a ray that grazes an operand over a span
 * shorter than it.
 *
 * <p><b>Materials and media.</b> A surface keeps its operand's material unless the Bool (or an
 * enclosing Bool) was given one, which then overrides every surface inside it and maps its
 * textures in that Bool's space (its placement and motion), not the leaf's, so the block is
 * textured as one solid ({@link Hit#materialSpace}; uv mapping still reads the leaf's uv). For refraction
 * and shadows the whole tree is one solid ({@link GObject#solid()} of every object in it is the
 * outermost Bool): a ray that enters it through one leaf may leave through another, and it
 * leaves the medium it entered. That medium is the material of the surface it entered by, so a
 * Bool with its own material is one medium throughout; without one, a union of glass and water
 * is filled with whichever it was entered through (give the Bool a material to make it
 * unambiguous).
 *
 * <p><b>Bounds.</b> A union's are its operands' together, an intersection's their overlap (an
 * empty intersection is skipped by the scene), a difference's its first operand's. An operand
 * whose bounds the ray misses is not asked for spans; for an intersection (or the first operand
 * of a difference) that alone settles that there is no hit.
 *
 * <p><b>Freezing.</b> Operands are frozen with the Bool's object-to-world placement as their
 * parent, so an operand's placement (and motion) is relative to the Bool's, and a moving Bool
 * moves its operands; their world bounds, and so the Bool's, cover the whole shutter. The Bool takes the next id and
 * its operands the following ones, depth first in operand order.
 *
 * <p><b>Sharing.</b> A scene freezes a copy of the whole tree ({@link #copy()} copies the
 * operands), so an operand stays the caller's to change between builds, and one object may be an
 * operand of several Bools (once per Bool) or also be added to the scene by itself: each place
 * gets its own frozen copy. Since a shared operand is copied once per place it is used, the
 * objects a tree expands to are counted as it is made and limited to {@link #MAX_OBJECTS}.
 */
public final class Bool extends GObject {
    /** The operation of a {@link Bool}. */
    public enum Op {
        /** Inside any operand. */
        UNION,
        /** Inside every operand. */
        INTERSECTION,
        /** Inside the first operand and none of the others. */
        DIFFERENCE;

        /**
         * The scene-language keyword: "union", "intersection" or "difference".
         *
         * @return the keyword, in lower case as the scene language writes it
         */
        public String keyword() {
            return switch (this) {
                case UNION -> "union";
                case INTERSECTION -> "intersection";
                case DIFFERENCE -> "difference";
            };
        }
    }

    /** Relative tie tolerance for coincident operand surfaces (see the class comment). */
    public static final double TIE = 1e-9;

    /**
     * The deepest CSG nesting allowed: a Bool whose operands are not Bools is 1 level, a Bool with
     * a Bool operand one more than that operand. Building, bounds, materials and every ray recurse
     * once (or twice) per level; the limit keeps that within a known stack, measured compiled and
     * interpreted alike (docs/performance.md, bounded resources): freezing stays well within a
     * thread's default stack, and a ray, under the deepest mirror bounces, within a fraction of
     * the render thread's, which the renderer makes large ({@code Renderer}). The parser reads
     * nested blocks without recursion and refuses a deeper one at its keyword. Union and intersection take
     * any number of operands, so a long chain of them never needs to nest.
     */
    public static final int MAX_NESTING = 1000;

    /**
     * The most objects one tree may expand to, counting this node and each operand once per
     * place it is used: a Bool reused as an operand of the next one, level after level, would
     * otherwise double the copies a scene makes at each level. Far above any tree written by hand
     * or read from a scene file (where every operand is a new object).
     */
    public static final long MAX_OBJECTS = 10_000_000;

    private final Op op;
    /** The caller's operands; in a frozen copy, its own frozen copies of them ({@link #copy()}). */
    private GObject[] operands;
    private List<GObject> operandList;
    /** The material given to this Bool itself (not an inherited one); overrides the operands'. */
    private Material own;
    /** Levels of CSG in this node's tree: 1 + the deepest Bool operand's (see {@link #MAX_NESTING}). */
    private final int nesting;
    /** Objects this tree expands to when copied: 1 + each operand's (see {@link #MAX_OBJECTS}). */
    private final long objectCount;

    /**
     * An n-ary CSG node: union or intersection of all operands; difference = the first minus all
     * the others.
     *
     * @param op       the operation
     * @param operands the operands, in order (the list is copied; the operands are not changed)
     * @throws IllegalArgumentException if there are fewer than two operands, or an operand is
     *         null, an object of a built scene, given twice, not closed ("union operand 2
     *         (mesh) is not closed: it has 4 boundary edges", operands counted from 1), nested
     *         deeper than {@link #MAX_NESTING} or the tree would expand to more than
     *         {@link #MAX_OBJECTS} objects
     */
    public Bool(Op op, List<GObject> operands) {
        if (op == null) throw new IllegalArgumentException("CSG operation is missing");
        if (operands == null || operands.size() < 2) {
            throw new IllegalArgumentException(op.keyword() + " needs at least 2 operands, found " + (operands == null ? 0 : operands.size()));
        }
        this.op = op;
        this.operands = new GObject[operands.size()];
        Map<GObject, Integer> seen = new IdentityHashMap<>();
        int deepest = 0;
        long count = 1;
        for (int i = 0; i < operands.size(); i++) {
            GObject o = operands.get(i);
            String which = op.keyword() + " operand " + (i + 1);
            if (o == null) throw new IllegalArgumentException(which + " is missing");
            if (o.isFrozen()) throw new IllegalArgumentException(which + " (" + MessageText.cut(o.name()) + ") is an object of a built scene; give the object it was built from");
            Integer before = seen.put(o, i);
            if (before != null) throw new IllegalArgumentException(which + " (" + MessageText.cut(o.name()) + ") is the same object as operand " + (before + 1));
            if (o instanceof TriangleMesh m && m.triangleCount() == 0) {
                int zero = m.degenerateCount();
                throw new IllegalArgumentException(which + " (" + MessageText.cut(o.name()) + ") is empty: "
                        + (zero == 0 ? "it has no faces" : "all of its " + zero + " triangles have zero area") + ", so it has no inside");
            }
            if (!o.isClosed()) {
                int n = boundaryEdges(o);
                throw new IllegalArgumentException(which + " (" + MessageText.cut(o.name()) + ") is not closed: "
                        + (n >= 0 ? "it has " + n + " boundary edges" : "it has no inside"));
            }
            if (o instanceof Bool b && b.nesting >= MAX_NESTING) {
                throw new IllegalArgumentException("CSG nesting deeper than " + MAX_NESTING + " levels: " + which + " (" + MessageText.cut(o.name())
                        + ") is " + b.nesting + " levels deep (union and intersection take any number of operands, so a long chain can be one node)");
            }
            if (o instanceof Bool b) deepest = Math.max(deepest, b.nesting);
            count += o.objectCount();
            if (count > MAX_OBJECTS) {
                throw new IllegalArgumentException(which + " (" + MessageText.cut(o.name()) + ") brings the CSG tree to more than " + MAX_OBJECTS
                        + " objects, counting an operand used in several places once per place");
            }
            this.operands[i] = o;
        }
        this.nesting = deepest + 1;
        this.objectCount = count;
        this.operandList = Collections.unmodifiableList(new ArrayList<>(operands));
    }

    /** A copy of the tree: this node's description and a copy of each operand (see the class comment). */
    @Override
    protected Bool copy() {
        Bool c = (Bool) super.copy();
        c.operands = new GObject[operands.length];
        for (int i = 0; i < operands.length; i++) c.operands[i] = operands[i].copy();
        c.operandList = Collections.unmodifiableList(java.util.Arrays.asList(c.operands.clone()));
        return c;
    }

    /** Boundary edges of an open operand, or -1 for a kind of object that has no edges to count. */
    private static int boundaryEdges(GObject o) {
        if (o instanceof TriangleMesh m) return m.boundaryEdgeCount();
        if (o instanceof SubdivisionSurface s) return s.boundaryEdgeCount();
        if (o instanceof Triangle) return 3;
        return -1;
    }

    /**
     * The operation.
     *
     * @return how the operands are combined
     */
    public Op op() { return op; }

    @Override long objectCount() { return objectCount; }

    @Override
    boolean movesAnything() {
        if (isMoving()) return true;
        for (GObject o : operands) if (o.movesAnything()) return true;
        return false;
    }

    /**
     * Levels of CSG nesting in this node's tree, counting this one: 1 if no operand is a Bool.
     *
     * @return the nesting depth, at least 1
     */
    public int nesting() { return nesting; }

    /**
     * The operands in the order given (read-only); a frozen Bool's are its own frozen copies.
     *
     * @return a read-only list of the operands
     */
    public List<GObject> operands() { return operandList; }

    // ---- builder methods, returning this type (see GObject for what each does) ----

    /** {@inheritDoc} */
    @Override public Bool transform(Transform t) { super.transform(t); return this; }

    /** {@inheritDoc} */
    @Override public Bool motion(Motion m) { super.motion(m); return this; }

    /** {@inheritDoc} */
    @Override public Bool material(Material m) { super.material(m); return this; }

    /** {@inheritDoc} */
    @Override public Bool name(String n) { super.name(n); return this; }

    /** {@inheritDoc} */
    @Override public Bool source(String where) { super.source(where); return this; }

    /** {@inheritDoc} */
    @Override public Bool source(String file, int line, int column) { super.source(file, line, column); return this; }

    /** The operation's keyword: "union", "intersection" or "difference". */
    @Override public String kind() { return op.keyword(); }

    /** Always true: a CSG result bounds a volume. */
    @Override public boolean isClosed() { return true; }

    // ---- freezing and bounds ----

    /** Freezes the operands under this node's placement and material, then this node. */
    @Override
    protected int freeze(BuildContext context, int ids) {
        if (isFrozen()) throw new IllegalStateException(name() + " is frozen already");
        own = material();
        Placement toWorld = placementIn(context.placement());
        BuildContext inner = context.within(toWorld, own != null ? own : context.material());
        // The outermost Bool: an enclosing Bool's freeze made it ours before freezing us (until then
        // an operand's solid is the Bool it was given to); a Bool frozen on its own is its own. Set
        // on the way down, so each object is marked once, not once per enclosing level.
        GObject top = solid();
        int next = ids + 1;
        for (int i = 0; i < operands.length; i++) {
            operands[i].solid(top);
            try {
                next = operands[i].freeze(inner, next);
            } catch (IllegalArgumentException e) {
                throw SceneBuildException.of(operands[i], e).inOperand(this, i);
            }
        }
        // Last, because the world bounds are computed from the frozen operands'.
        super.freeze(context, ids);
        return next;
    }

    /** Union: all operands' bounds; intersection: their overlap; difference: the first operand's. */
    @Override
    protected Bounds computeWorldBounds() {
        Bounds b = operands[0].bounds();
        for (int i = 1; i < operands.length && op != Op.DIFFERENCE; i++) {
            b = op == Op.UNION ? b.union(operands[i].bounds()) : b.intersection(operands[i].bounds());
        }
        return b;
    }

    /** Union: the operands' placed local bounds together, intersection: their overlap, difference: the first's (in this Bool's space). */
    @Override
    public Bounds localBounds() {
        Bounds b = placed(operands[0]);
        for (int i = 1; i < operands.length && op != Op.DIFFERENCE; i++) {
            b = op == Op.UNION ? b.union(placed(operands[i])) : b.intersection(placed(operands[i]));
        }
        return b;
    }

    /**
     * An operand's local bounds placed by its transform and carried along its keys and its motion
     * (before freezing, over the default shutter; after, over the one it was frozen for).
     */
    private static Bounds placed(GObject o) {
        Bounds b = o.localBounds().transformed(o.transform());
        if (o.keys() != null) b = o.keys().sweep(b, o.shutterOpen(), o.shutterClose());
        Motion m = o.motion();
        return m == null ? b : m.resolve(Placement.OPEN, Placement.CLOSE).sweep(b);
    }

    /** This Bool's material; the operands' only where it has none of its own (they are never shaded otherwise). */
    @Override
    public void forEachMaterial(Consumer<Material> visitor) {
        visitor.accept(material());
        if (own == null) for (GObject o : operands) o.forEachMaterial(visitor);
    }

    // ---- rays ----

    /**
     * The operand that alone decides the ray within (tMin, tMax), or null: a difference's first
     * operand when the ray misses every subtracted operand's bounds, a union's only operand whose
     * bounds it enters. Then its own nearest hit (or any-hit) is the result and no spans are
     * needed: the common case, for most rays pass by the cut.
     */
    private GObject sole(Ray ray) {
        if (op == Op.INTERSECTION) return null;
        GObject only = null;
        for (int i = 0; i < operands.length; i++) {
            if (!operands[i].bounds().hitRange(ray, null)) continue;
            if (op == Op.DIFFERENCE && i > 0 || only != null) return null;
            only = operands[i];
        }
        return only;
    }

    /** The nearest boundary of the result: a leaf's surface (see the class comment). */
    @Override
    public boolean intersect(Ray ray, Hit hit, TraceContext ctx) {
        GObject only = sole(ray);
        if (only != null) {
            if (!only.intersect(ray, hit, ctx)) return false;
            if (own != null) {
                hit.material = own;
                hit.materialSpace = this;
            }
            return true;
        }
        SpanBuffer out = ctx.acquireSpans();
        try {
            combine(ray, out, ctx);
            int e = firstBoundary(out, ray.tMin, ray.tMax);
            if (e < 0) return false;
            out.toHit(e, hit);
            return true;
        } finally {
            ctx.releaseSpans();
        }
    }

    /** True if the result has a boundary in (tMin, tMax). */
    @Override
    public boolean occluded(Ray ray, TraceContext ctx) {
        GObject only = sole(ray);
        if (only != null) return only.occluded(ray, ctx);
        SpanBuffer out = ctx.acquireSpans();
        try {
            combine(ray, out, ctx);
            return firstBoundary(out, ray.tMin, ray.tMax) >= 0;
        } finally {
            ctx.releaseSpans();
        }
    }

    /**
     * Appends the result's spans that overlap (tMin, tMax). The operands are asked about the whole
     * line so that the endpoints reported are the true ones even outside the range (a union's span
     * may begin in an operand span that ends before tMin).
     */
    @Override
    public void spans(Ray ray, SpanBuffer out, TraceContext ctx) {
        double tMin = ray.tMin, tMax = ray.tMax;
        SpanBuffer all = ctx.acquireSpans();
        try {
            ray.tMin = Double.NEGATIVE_INFINITY;
            ray.tMax = Double.POSITIVE_INFINITY;
            try {
                combine(ray, all, ctx);
            } finally {
                ray.tMin = tMin;
                ray.tMax = tMax;
            }
            for (int s = 0; s < all.size(); s++) {
                if (all.exit(s) > tMin && all.entry(s) < tMax) {
                    out.addEndpoint(all, 2 * s, false);
                    out.addEndpoint(all, 2 * s + 1, false);
                }
            }
        } finally {
            ctx.releaseSpans();
        }
    }

    /** Index of the first endpoint in (tMin, tMax), or -1. */
    private static int firstBoundary(SpanBuffer b, double tMin, double tMax) {
        for (int s = 0; s < b.size(); s++) {
            double in = b.entry(s);
            if (in > tMin) return in < tMax ? 2 * s : -1;
            double out = b.exit(s);
            if (out > tMin) return out < tMax ? 2 * s + 1 : -1;
        }
        return -1;
    }

    /**
     * The result's spans overlapping (ray.tMin, ray.tMax), appended to {@code out}: exact
     * endpoints inside the range (the operands' spans there are complete), endpoints outside it
     * possibly those of a clipped operand span (callers wanting true ones widen the range).
     */
    private void combine(Ray ray, SpanBuffer out, TraceContext ctx) {
        if (!bounds().hitRange(ray, null)) return;
        int n = operands.length;
        // All operands' spans go into one pooled buffer, one run per operand; the runs' cursors and
        // ends live in the traversal stack above ctx.stackTop, raised while the operands (which may
        // be Bools or meshes using the stack themselves) are asked.
        SpanBuffer all = ctx.acquireSpans();
        int base = ctx.stackTop;
        int[] run = ctx.stack(base + 2 * n);
        ctx.stackTop = base + 2 * n;
        try {
            for (int i = 0; i < n; i++) {
                GObject o = operands[i];
                int from = all.size();
                // An operand the ray misses contributes no span; for an intersection (or the first
                // operand of a difference) that empties the whole result.
                if (o.bounds().hitRange(ray, null)) o.spans(ray, all, ctx);
                if (all.size() == from && (op == Op.INTERSECTION || op == Op.DIFFERENCE && i == 0)) return;
                run[base + 2 * i] = 2 * from;
                run[base + 2 * i + 1] = 2 * all.size();
            }
            if (own != null) all.overrideMaterial(own, this);
            merge(ray, all, run, base, out);
        } finally {
            ctx.stackTop = base;
            ctx.releaseSpans();
        }
    }

    /**
     * Sweeps the operands' endpoints in order of t, applying each event (endpoints within the tie
     * tolerance) at once and emitting a boundary where the result's inside state changes.
     * {@code run[base + 2i]} is operand i's cursor into {@code all}, {@code run[base + 2i + 1]} its end.
     */
    private void merge(Ray ray, SpanBuffer all, int[] run, int base, SpanBuffer out) {
        int n = operands.length;
        double dlen = Math.sqrt(ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz);
        double originScale = 1 + Math.max(Math.abs(ray.ox), Math.max(Math.abs(ray.oy), Math.abs(ray.oz)));
        int keptInside = 0;       // operands the ray is inside, the first one only for a difference
        int subtractedInside = 0; // subtracted operands the ray is inside (difference)
        boolean inside = false;
        int entry = -1, entryOperand = -1;
        while (true) {
            // The next event: the smallest pending endpoint and everything within the tie tolerance.
            double tNext = Double.POSITIVE_INFINITY;
            boolean any = false;
            for (int i = 0; i < n; i++) {
                int c = run[base + 2 * i];
                if (c < run[base + 2 * i + 1]) {
                    double t = all.t(c);
                    if (!any || t < tNext) tNext = t;
                    any = true;
                }
            }
            if (!any) break;
            double limit = Double.isInfinite(tNext) ? tNext : tNext + TIE * (originScale + Math.abs(tNext) * dlen) / dlen;
            int up = -1, upOperand = -1, down = -1, downOperand = -1;
            for (int i = 0; i < n; i++) {
                int c = run[base + 2 * i], end = run[base + 2 * i + 1];
                boolean subtracted = op == Op.DIFFERENCE && i > 0;
                while (c < end && all.t(c) <= limit) {
                    boolean entering = (c & 1) == 0; // runs start at even indices: entries are even
                    if (subtracted) subtractedInside += entering ? 1 : -1;
                    else keptInside += entering ? 1 : -1;
                    // Does this endpoint on its own move the result inwards (up) or outwards (down)?
                    if (entering != subtracted) {
                        if (up < 0) { up = c; upOperand = i; }
                    } else if (down < 0) {
                        down = c; downOperand = i;
                    }
                    c++;
                }
                run[base + 2 * i] = c;
            }
            boolean now = switch (op) {
                case UNION -> keptInside > 0;
                case INTERSECTION -> keptInside == n;
                case DIFFERENCE -> keptInside > 0 && subtractedInside == 0;
            };
            if (now == inside) continue;
            inside = now;
            if (now) {
                entry = up;
                entryOperand = upOperand;
            } else if (all.t(down) > ray.tMin && all.t(entry) < ray.tMax) {
                out.addEndpoint(all, entry, op == Op.DIFFERENCE && entryOperand > 0);
                out.addEndpoint(all, down, op == Op.DIFFERENCE && downOperand > 0);
            }
        }
    }

    @Override
    protected boolean intersectLocal(Ray ray, Hit hit, TraceContext ctx) {
        // A Bool has no surface of its own: its operands, frozen with its transform, answer world rays.
        throw new UnsupportedOperationException("a CSG node is intersected through its operands");
    }

    @Override
    protected void shadeLocal(double x, double y, double z, Hit hit, ShadingData sd) {
        // Hits name the leaf surface, which shades itself.
        throw new UnsupportedOperationException("a CSG node is shaded through the leaf surface hit");
    }
}
