package lt.spindulys.scene;

import lt.spindulys.material.Material;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;

/**
 * {@link Bool} against an independent reference written here: analytic world-space spans of
 * spheres, boxes and capped cylinders under arbitrary affine placements (its own matrices and
 * inverses), combined by pairwise interval algebra (merge for union, overlap for intersection,
 * overlap with the complement for difference), with none of Bool's, SpanBuffer's or the shapes'
 * code. 100,000 seeded rays through random nested trees must agree on hit or miss, the distance
 * (1e-9), the leaf hit and whether its normal is flipped, the shaded world normal (1e-9), the
 * material (leaves' own, overridden by the outermost Bool that has one), the spans of the whole
 * tree, and occlusion.
 *
 * <p>Skip rule (narrow, counted, and bounded by the test): a ray is not compared when two
 * endpoints of leaf spans (any leaves, including the entry and exit of one leaf) lie within
 * {@link #TIE_SKIP} of each other or of the ray's tMin or tMax, or when the reference's hit lies
 * within {@link #TIE_SKIP} of a box edge or cylinder rim (the face reported there is a tie). The
 * test fails if more than 1% of the rays are skipped (with this seed, 3 of 100,000 are). There the
 * order of events is decided by rounding (Bool deliberately merges events within 1e-9, see its
 * tie rule) and near-tangent roots lose half their digits.
 */
class BoolReferenceTest {
    private static final int TREES = 2000, RAYS_PER_TREE = 50;
    private static final double TOL = 1e-9;
    /** Distance (in units of t along rays of length about 1) under which events count as a tie. */
    private static final double TIE_SKIP = 1e-6;

    // ---- the reference: affine maps ----

    /** Row-major 3x4 matrix times point. */
    private static double[] point(double[] m, double x, double y, double z) {
        return new double[] {m[0] * x + m[1] * y + m[2] * z + m[3], m[4] * x + m[5] * y + m[6] * z + m[7], m[8] * x + m[9] * y + m[10] * z + m[11]};
    }

    private static double[] vector(double[] m, double x, double y, double z) {
        return new double[] {m[0] * x + m[1] * y + m[2] * z, m[4] * x + m[5] * y + m[6] * z, m[8] * x + m[9] * y + m[10] * z};
    }

    /** a after b (apply b first). */
    private static double[] compose(double[] a, double[] b) {
        double[] r = new double[12];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 4; j++) {
                double s = j == 3 ? a[4 * i + 3] : 0;
                for (int k = 0; k < 3; k++) s += a[4 * i + k] * b[4 * k + j];
                r[4 * i + j] = s;
            }
        }
        return r;
    }

    private static double[] inverse(double[] m) {
        double a = m[0], b = m[1], c = m[2], d = m[4], e = m[5], f = m[6], g = m[8], h = m[9], i = m[10];
        double A = e * i - f * h, B = -(d * i - f * g), C = d * h - e * g;
        double det = a * A + b * B + c * C;
        double[] r = {
                A / det, -(b * i - c * h) / det, (b * f - c * e) / det, 0,
                B / det, (a * i - c * g) / det, -(a * f - c * d) / det, 0,
                C / det, -(a * h - b * g) / det, (a * e - b * d) / det, 0};
        double[] t = vector(r, m[3], m[7], m[11]);
        r[3] = -t[0]; r[7] = -t[1]; r[11] = -t[2];
        return r;
    }

    private static double[] randomMatrix(Random rnd, double spread) {
        // scale, then rotate about a random axis, then move
        double sx = 0.6 + 0.8 * rnd.nextDouble(), sy = 0.6 + 0.8 * rnd.nextDouble(), sz = 0.6 + 0.8 * rnd.nextDouble();
        double[] ax = unit(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
        double ang = 2 * Math.PI * rnd.nextDouble(), c = Math.cos(ang), s = Math.sin(ang), t = 1 - c;
        double x = ax[0], y = ax[1], z = ax[2];
        double[] rot = {t * x * x + c, t * x * y - s * z, t * x * z + s * y, 0,
                t * x * y + s * z, t * y * y + c, t * y * z - s * x, 0,
                t * x * z - s * y, t * y * z + s * x, t * z * z + c, 0};
        double[] scale = {sx, 0, 0, 0, 0, sy, 0, 0, 0, 0, sz, 0};
        double[] m = compose(rot, scale);
        m[3] = spread * (2 * rnd.nextDouble() - 1);
        m[7] = spread * (2 * rnd.nextDouble() - 1);
        m[11] = spread * (2 * rnd.nextDouble() - 1);
        return m;
    }

    private static double[] unit(double x, double y, double z) {
        double l = Math.sqrt(x * x + y * y + z * z);
        return new double[] {x / l, y / l, z / l};
    }

    private static final double[] IDENTITY = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

    // ---- the reference: spans ----

    /** A span endpoint: where, which leaf, its world normal (outward of the leaf), flipped or not. */
    record End(double t, GObject leaf, double[] normal, boolean flip, double margin) {
        End flipped() { return new End(t, leaf, normal, !flip, margin); }
    }

    record Span(End in, End out) {}

    /** A node of the reference tree, mirroring a Bool tree built from it. */
    interface Node {
        /** Spans along the whole line o + t d (world space), sorted and disjoint. */
        List<Span> spans(double[] o, double[] d);

        /** Every leaf span endpoint t (for the tie skip rule). */
        void leafEvents(double[] o, double[] d, List<Double> out);

        GObject object();
    }

    /** A leaf: local shape, world placement; the GObject made from it has the same placement. */
    abstract static class Leaf implements Node {
        final double[] toWorld, toLocal;
        GObject object;

        Leaf(double[] toWorld) {
            this.toWorld = toWorld;
            this.toLocal = inverse(toWorld);
        }

        @Override public GObject object() { return object; }

        @Override public List<Span> spans(double[] o, double[] d) {
            double[] lo = point(toLocal, o[0], o[1], o[2]), ld = vector(toLocal, d[0], d[1], d[2]);
            double[] r = local(lo, ld); // tIn, tOut, nIn xyz, nOut xyz, marginIn, marginOut
            if (r == null || !(r[1] > r[0])) return List.of();
            return List.of(new Span(new End(r[0], object, world(r[2], r[3], r[4]), false, r[8]),
                    new End(r[1], object, world(r[5], r[6], r[7]), false, r[9])));
        }

        @Override public void leafEvents(double[] o, double[] d, List<Double> out) {
            double[] lo = point(toLocal, o[0], o[1], o[2]), ld = vector(toLocal, d[0], d[1], d[2]);
            double[] r = local(lo, ld);
            if (r != null) { out.add(r[0]); out.add(r[1]); }
        }

        /** Local normal to world: inverse transpose, normalised. */
        double[] world(double x, double y, double z) {
            double[] m = toLocal;
            return unit(m[0] * x + m[4] * y + m[8] * z, m[1] * x + m[5] * y + m[9] * z, m[2] * x + m[6] * y + m[10] * z);
        }

        /** Local entry/exit with local normals and the margins to the runner-up surface, or null. */
        abstract double[] local(double[] o, double[] d);
    }

    static final class RefSphere extends Leaf {
        final double cx, cy, cz, r;

        RefSphere(double[] m, double cx, double cy, double cz, double r) {
            super(m);
            this.cx = cx; this.cy = cy; this.cz = cz; this.r = r;
            object = new Sphere(new Vec3(cx, cy, cz), r).transform(Transform.ofMatrix(m));
        }

        @Override double[] local(double[] o, double[] d) {
            double px = o[0] - cx, py = o[1] - cy, pz = o[2] - cz;
            double a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            double b = px * d[0] + py * d[1] + pz * d[2];
            double c = px * px + py * py + pz * pz - r * r;
            double disc = b * b - a * c;
            if (disc < 0) return null;
            double sq = Math.sqrt(disc);
            double t0 = (-b - sq) / a, t1 = (-b + sq) / a;
            return new double[] {t0, t1,
                    px + t0 * d[0], py + t0 * d[1], pz + t0 * d[2],
                    px + t1 * d[0], py + t1 * d[1], pz + t1 * d[2], Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        }
    }

    static final class RefBox extends Leaf {
        final double[] lo, hi;

        RefBox(double[] m, double[] lo, double[] hi) {
            super(m);
            this.lo = lo;
            this.hi = hi;
            object = new Box(new Vec3(lo[0], lo[1], lo[2]), new Vec3(hi[0], hi[1], hi[2])).transform(Transform.ofMatrix(m));
        }

        @Override double[] local(double[] o, double[] d) {
            // All three slab entries and exits; the last entry and first exit bound the box.
            double[] tin = new double[3], tout = new double[3];
            for (int a = 0; a < 3; a++) {
                if (d[a] == 0) {
                    if (o[a] < lo[a] || o[a] > hi[a]) return null;
                    tin[a] = Double.NEGATIVE_INFINITY;
                    tout[a] = Double.POSITIVE_INFINITY;
                } else {
                    double t1 = (lo[a] - o[a]) / d[a], t2 = (hi[a] - o[a]) / d[a];
                    tin[a] = Math.min(t1, t2);
                    tout[a] = Math.max(t1, t2);
                }
            }
            int ai = argmax(tin), ao = argmin(tout);
            double second = Double.NEGATIVE_INFINITY, secondOut = Double.POSITIVE_INFINITY;
            for (int a = 0; a < 3; a++) {
                if (a != ai) second = Math.max(second, tin[a]);
                if (a != ao) secondOut = Math.min(secondOut, tout[a]);
            }
            double[] r = new double[10];
            r[0] = tin[ai];
            r[1] = tout[ao];
            r[2 + ai] = d[ai] > 0 ? -1 : 1;
            r[5 + ao] = d[ao] > 0 ? 1 : -1;
            r[8] = tin[ai] - second;
            r[9] = secondOut - tout[ao];
            return r;
        }

        private static int argmax(double[] a) { return a[0] >= a[1] ? (a[0] >= a[2] ? 0 : 2) : (a[1] >= a[2] ? 1 : 2); }
        private static int argmin(double[] a) { return a[0] <= a[1] ? (a[0] <= a[2] ? 0 : 2) : (a[1] <= a[2] ? 1 : 2); }
    }

    static final class RefCylinder extends Leaf {
        final double[] base, w; // base point and unit axis
        final double h, r;

        RefCylinder(double[] m, double[] base, double[] top, double r) {
            super(m);
            this.base = base;
            double[] axis = {top[0] - base[0], top[1] - base[1], top[2] - base[2]};
            this.h = Math.sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
            this.w = unit(axis[0], axis[1], axis[2]);
            this.r = r;
            object = new Cylinder(new Vec3(base[0], base[1], base[2]), new Vec3(top[0], top[1], top[2]), r).transform(Transform.ofMatrix(m));
        }

        @Override double[] local(double[] o, double[] d) {
            double qx = o[0] - base[0], qy = o[1] - base[1], qz = o[2] - base[2];
            double oz = qx * w[0] + qy * w[1] + qz * w[2], dz = d[0] * w[0] + d[1] * w[1] + d[2] * w[2];
            // Components perpendicular to the axis.
            double px = qx - oz * w[0], py = qy - oz * w[1], pz = qz - oz * w[2];
            double ex = d[0] - dz * w[0], ey = d[1] - dz * w[1], ez = d[2] - dz * w[2];
            double capIn, capOut;
            double[] capInN, capOutN;
            if (dz == 0) {
                if (oz < 0 || oz > h) return null;
                capIn = Double.NEGATIVE_INFINITY; capOut = Double.POSITIVE_INFINITY;
                capInN = capOutN = null;
            } else {
                double tb = -oz / dz, tt = (h - oz) / dz;
                double[] down = {-w[0], -w[1], -w[2]};
                if (dz > 0) { capIn = tb; capInN = down; capOut = tt; capOutN = w; }
                else { capIn = tt; capInN = w; capOut = tb; capOutN = down; }
            }
            double a = ex * ex + ey * ey + ez * ez, b = px * ex + py * ey + pz * ez, c = px * px + py * py + pz * pz - r * r;
            double sideIn, sideOut;
            if (a == 0) {
                if (c > 0) return null;
                sideIn = Double.NEGATIVE_INFINITY; sideOut = Double.POSITIVE_INFINITY;
            } else {
                double disc = b * b - a * c;
                if (disc < 0) return null;
                double sq = Math.sqrt(disc);
                sideIn = (-b - sq) / a;
                sideOut = (-b + sq) / a;
            }
            double[] res = new double[10];
            if (sideIn > capIn) {
                res[0] = sideIn;
                res[2] = px + sideIn * ex; res[3] = py + sideIn * ey; res[4] = pz + sideIn * ez;
            } else {
                res[0] = capIn;
                res[2] = capInN[0]; res[3] = capInN[1]; res[4] = capInN[2];
            }
            if (sideOut < capOut) {
                res[1] = sideOut;
                res[5] = px + sideOut * ex; res[6] = py + sideOut * ey; res[7] = pz + sideOut * ez;
            } else {
                res[1] = capOut;
                res[5] = capOutN[0]; res[6] = capOutN[1]; res[7] = capOutN[2];
            }
            res[8] = Math.abs(sideIn - capIn);
            res[9] = Math.abs(sideOut - capOut);
            if (!(res[0] <= res[1])) return null;
            return res;
        }
    }

    static final class RefBool implements Node {
        final Bool.Op op;
        final List<Node> children;
        final Bool object;
        final double[] own;

        RefBool(Bool.Op op, List<Node> children, double[] own) {
            this.op = op;
            this.own = own;
            this.children = children;
            List<GObject> ops = new ArrayList<>();
            for (Node n : children) ops.add(n.object());
            object = new Bool(op, ops);
            object.transform(Transform.ofMatrix(own));
        }

        @Override public GObject object() { return object; }

        @Override public List<Span> spans(double[] o, double[] d) {
            List<Span> acc = children.get(0).spans(o, d);
            for (int i = 1; i < children.size(); i++) {
                List<Span> next = children.get(i).spans(o, d);
                acc = switch (op) {
                    case UNION -> union(acc, next);
                    case INTERSECTION -> intersection(acc, next);
                    case DIFFERENCE -> intersection(acc, complement(next));
                };
            }
            return acc;
        }

        @Override public void leafEvents(double[] o, double[] d, List<Double> out) {
            for (Node n : children) n.leafEvents(o, d, out);
        }
    }

    static List<Span> union(List<Span> a, List<Span> b) {
        List<Span> all = new ArrayList<>(a);
        all.addAll(b);
        all.sort((x, y) -> Double.compare(x.in().t(), y.in().t()));
        List<Span> out = new ArrayList<>();
        for (Span s : all) {
            if (!out.isEmpty() && s.in().t() <= out.get(out.size() - 1).out().t()) {
                Span last = out.remove(out.size() - 1);
                out.add(new Span(last.in(), s.out().t() > last.out().t() ? s.out() : last.out()));
            } else {
                out.add(s);
            }
        }
        return out;
    }

    static List<Span> intersection(List<Span> a, List<Span> b) {
        List<Span> out = new ArrayList<>();
        for (Span x : a) {
            for (Span y : b) {
                End in = x.in().t() >= y.in().t() ? x.in() : y.in();
                End o = x.out().t() <= y.out().t() ? x.out() : y.out();
                if (in.t() < o.t()) out.add(new Span(in, o));
            }
        }
        out.sort((p, q) -> Double.compare(p.in().t(), q.in().t()));
        return out;
    }

    /** The gaps between b's spans, from -inf to +inf, bounded by b's surfaces flipped. */
    static List<Span> complement(List<Span> b) {
        List<Span> out = new ArrayList<>();
        End prev = new End(Double.NEGATIVE_INFINITY, null, null, false, Double.POSITIVE_INFINITY);
        for (Span s : b) {
            out.add(new Span(prev, s.in().flipped()));
            prev = s.out().flipped();
        }
        out.add(new Span(prev, new End(Double.POSITIVE_INFINITY, null, null, false, Double.POSITIVE_INFINITY)));
        return out;
    }

    // ---- random trees ----

    private static final Material[] PALETTE = {
            Material.builder().name("red").build(), Material.builder().name("green").build(), Material.builder().name("blue").build()};

    private static Node randomTree(Random rnd, int depth) {
        if (depth == 0 || rnd.nextInt(4) == 0) {
            Node leaf = randomLeaf(rnd);
            if (rnd.nextBoolean()) leaf.object().material(PALETTE[rnd.nextInt(PALETTE.length)]);
            return leaf;
        }
        Bool.Op op = Bool.Op.values()[rnd.nextInt(3)];
        int n = 2 + (rnd.nextInt(3) == 0 ? 1 : 0);
        List<Node> kids = new ArrayList<>();
        for (int i = 0; i < n; i++) kids.add(randomTree(rnd, depth - 1));
        double[] own = rnd.nextInt(3) == 0 ? IDENTITY.clone() : randomMatrix(rnd, 0.3);
        RefBool b = new RefBool(op, kids, own);
        if (rnd.nextInt(5) == 0) b.object.material(PALETTE[rnd.nextInt(PALETTE.length)]);
        return b;
    }

    /**
     * The material each leaf must be shaded with: that of the outermost Bool that has one, else
     * the leaf's own, else the scene default.
     */
    private static void expectMaterials(Node n, Material override, java.util.Map<GObject, Material> out) {
        if (n instanceof RefBool b) {
            Material o = override != null ? override : b.object.material();
            for (Node c : b.children) expectMaterials(c, o, out);
        } else {
            Material own = n.object().material();
            out.put(n.object(), override != null ? override : own != null ? own : Material.DEFAULT);
        }
    }

    private static Node randomLeaf(Random rnd) {
        double[] m = rnd.nextInt(5) == 0 ? IDENTITY.clone() : randomMatrix(rnd, 0.6);
        switch (rnd.nextInt(3)) {
            case 0:
                return new RefSphere(m, 0.3 * rnd.nextGaussian(), 0.3 * rnd.nextGaussian(), 0.3 * rnd.nextGaussian(), 0.3 + 0.7 * rnd.nextDouble());
            case 1: {
                double[] lo = new double[3], hi = new double[3];
                for (int a = 0; a < 3; a++) {
                    double c = 0.3 * rnd.nextGaussian(), e = 0.2 + 0.6 * rnd.nextDouble();
                    lo[a] = c - e;
                    hi[a] = c + e;
                }
                return new RefBox(m, lo, hi);
            }
            default: {
                double[] base = {0.4 * rnd.nextGaussian(), 0.4 * rnd.nextGaussian(), 0.4 * rnd.nextGaussian()};
                double[] top = {0.4 * rnd.nextGaussian(), 0.4 * rnd.nextGaussian(), 0.4 * rnd.nextGaussian()};
                if (dist(base, top) < 0.2) top[1] += 0.5;
                return new RefCylinder(m, base, top, 0.15 + 0.5 * rnd.nextDouble());
            }
        }
    }

    private static double dist(double[] a, double[] b) {
        return Math.sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    }

    /** Mirrors the Bool's freeze composition: world = parent after own, down the tree. */
    private static void placeLeaves(Node n, double[] parentToWorld) {
        if (n instanceof Leaf l) {
            double[] world = compose(parentToWorld, l.toWorld);
            System.arraycopy(world, 0, l.toWorld, 0, 12);
            System.arraycopy(inverse(world), 0, l.toLocal, 0, 12);
        } else {
            RefBool b = (RefBool) n;
            double[] world = compose(parentToWorld, b.own);
            for (Node c : b.children) placeLeaves(c, world);
        }
    }

    // ---- the test ----

    @Test
    void randomTreesAgreeWithTheReference() {
        Random rnd = new Random(20261122);
        TraceContext ctx = new TraceContext();
        Hit hit = new Hit();
        ShadingData sd = new ShadingData();
        SpanBuffer spans = new SpanBuffer();
        int compared = 0, skipped = 0, hits = 0, flippedHits = 0, maxDepthSeen = 0;
        int[] opsSeen = new int[3];
        for (int tree = 0; tree < TREES; tree++) {
            Node root;
            do root = randomTree(rnd, 1 + rnd.nextInt(4)); while (!(root instanceof RefBool));
            maxDepthSeen = Math.max(maxDepthSeen, depth(root));
            countOps(root, opsSeen);
            placeLeaves(root, IDENTITY);
            java.util.Map<GObject, Material> materials = new java.util.IdentityHashMap<>();
            expectMaterials(root, null, materials);
            Bool bool = (Bool) root.object();
            TestBuild.freeze(bool, Transform.IDENTITY, Material.DEFAULT, 0);
            for (int k = 0; k < RAYS_PER_TREE; k++) {
                double[] o, d;
                if (k % 5 == 0) {
                    // From near the middle, where rays often start inside operands.
                    o = new double[] {0.5 * rnd.nextGaussian(), 0.5 * rnd.nextGaussian(), 0.5 * rnd.nextGaussian()};
                    d = unit(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
                } else {
                    double[] dir = unit(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
                    o = new double[] {4 * dir[0], 4 * dir[1], 4 * dir[2]};
                    double[] aim = {0.8 * rnd.nextGaussian(), 0.8 * rnd.nextGaussian(), 0.8 * rnd.nextGaussian()};
                    double len = 0.5 + rnd.nextDouble(); // directions of various lengths: t is not distance
                    d = new double[] {(aim[0] - o[0]) * len / 4, (aim[1] - o[1]) * len / 4, (aim[2] - o[2]) * len / 4};
                }
                double tMin = k % 7 == 0 ? rnd.nextDouble() : 0;
                double tMax = k % 3 == 0 ? 2 + 4 * rnd.nextDouble() : Double.POSITIVE_INFINITY;
                double dlen = Math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);

                List<Double> events = new ArrayList<>();
                root.leafEvents(o, d, events);
                events.sort(null);
                boolean tie = false;
                for (int i = 1; i < events.size(); i++) tie |= (events.get(i) - events.get(i - 1)) * dlen < TIE_SKIP;
                List<Span> ref = root.spans(o, d);
                End expected = null;
                for (Span s : ref) {
                    if (s.in().t() > tMin) { expected = s.in().t() < tMax ? s.in() : null; break; }
                    if (s.out().t() > tMin) { expected = s.out().t() < tMax ? s.out() : null; break; }
                }
                if (expected != null && expected.margin() * dlen < TIE_SKIP) tie = true;
                // Endpoints within the tie distance of tMin or tMax are a tie with the range too.
                for (double e : events) tie |= Math.abs(e - tMin) * dlen < TIE_SKIP || Math.abs(e - tMax) * dlen < TIE_SKIP;
                if (tie) { skipped++; continue; }
                compared++;

                Ray ray = new Ray().set(o[0], o[1], o[2], d[0], d[1], d[2], tMin, tMax);
                hit.reset(tMax);
                boolean found = bool.intersect(ray, hit, ctx);
                String where = "tree " + tree + " ray " + k;
                assertEquals(expected != null, found, where);
                assertEquals(found, bool.occluded(ray, ctx), where + " occluded");
                assertEquals(tMin, ray.tMin, where);
                assertEquals(tMax, ray.tMax, where);
                if (found) {
                    hits++;
                    assertEquals(expected.t(), hit.t, TOL * Math.max(1, Math.abs(expected.t())), where + " t");
                    assertSame(expected.leaf(), hit.object, where + " leaf");
                    assertEquals(expected.flip(), hit.flipNormal, where + " flip");
                    if (hit.flipNormal) flippedHits++;
                    hit.object.shade(ray, hit, sd);
                    double s = expected.flip() ? -1 : 1;
                    double[] n = expected.normal();
                    double err = Math.sqrt(sq(sd.ng[0] - s * n[0]) + sq(sd.ng[1] - s * n[1]) + sq(sd.ng[2] - s * n[2]));
                    if (!(err < TOL)) fail(where + " normal " + java.util.Arrays.toString(sd.ng) + " expected " + (s * n[0]) + " " + (s * n[1]) + " " + (s * n[2]));
                    assertSame(materials.get(hit.object), hit.material, where + " material");
                    assertSame(materials.get(hit.object), sd.material, where + " shaded material");
                }
                // The whole tree's spans overlapping the range, with their true endpoints.
                spans.clear();
                bool.spans(ray, spans, ctx);
                List<Span> overlapping = new ArrayList<>();
                for (Span sp : ref) if (sp.out().t() > tMin && sp.in().t() < tMax) overlapping.add(sp);
                assertEquals(overlapping.size(), spans.size(), where + " span count");
                for (int i = 0; i < spans.size(); i++) {
                    assertEndpoint(overlapping.get(i).in().t(), spans.entry(i), where);
                    assertEndpoint(overlapping.get(i).out().t(), spans.exit(i), where);
                }
            }
        }
        assertEquals(TREES * RAYS_PER_TREE, compared + skipped);
        assertTrue(compared + skipped >= 100_000);
        // The skip rule must stay narrow, and the trees must exercise what they claim to.
        assertTrue(skipped < (compared + skipped) / 100, "skipped " + skipped + " of " + (compared + skipped));
        assertTrue(hits > compared / 10, "hits " + hits);
        assertTrue(flippedHits > 500, "flipped " + flippedHits);
        assertTrue(maxDepthSeen >= 4, "depth " + maxDepthSeen);
        for (int c : opsSeen) assertTrue(c > 100);
    }

    private static void assertEndpoint(double expected, double actual, String where) {
        if (Double.isInfinite(expected)) assertEquals(expected, actual, where);
        else assertEquals(expected, actual, TOL * Math.max(1, Math.abs(expected)), where + " span endpoint");
    }

    private static double sq(double x) { return x * x; }

    private static int depth(Node n) {
        if (n instanceof RefBool b) {
            int d = 0;
            for (Node c : b.children) d = Math.max(d, depth(c));
            return d + 1;
        }
        return 1;
    }

    private static void countOps(Node n, int[] ops) {
        if (n instanceof RefBool b) {
            ops[b.op.ordinal()]++;
            for (Node c : b.children) countOps(c, ops);
        }
    }
}
