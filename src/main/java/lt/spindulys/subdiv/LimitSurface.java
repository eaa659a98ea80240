package lt.spindulys.subdiv;

/**
 * The exact limit surface of a control mesh, evaluated directly at any face's parameters (as
 * OpenSubdiv's {@code Bfr::Surface<double>} does), for tessellating each face as a grid at
 * per-edge rates without refining the mesh.
 *
 * <p><b>Parameterization</b> (Bfr's): a quad of Catmull-Clark or bilinear has (u,v) in [0,1]^2,
 * corner 0 at (0,0), corner 1 at (1,0), corner 2 at (1,1); a Loop triangle has corner 1 at (1,0),
 * corner 2 at (0,1) and u + v &le; 1; any other face of N corners is N quad sub-faces, sub-face q
 * (at corner q) covering [q % w, q % w + 1/2] x [q / w, q / w + 1/2] with w = {@link #subFaceColumns}
 * columns, running from corner q (its (0,0)) along the edge leaving it to the face's centre.
 * Derivatives are with respect to the face's (u,v).
 *
 * <p><b>How each face is evaluated.</b> Regular faces (a bicubic B-spline patch of Catmull-Clark,
 * a quartic box-spline patch of Loop) and bilinear faces are single polynomial patches. Any other
 * face goes through local feature-adaptive refinement of its one-ring, as Bfr does: the sub-face
 * holding (u,v) is refined until it is a regular patch, and irregular sub-faces end at Bfr's
 * approximation levels in Far's Gregory end patches. An evaluator made for level L refines
 * irregular sub-faces to at least level L ({@code smooth = max(2, L)}, {@code sharp = max(6, L)}),
 * so every grid point at rate 2^L lies at a corner of a regular patch or of an end patch of level
 * L or deeper: a vertex of the level-L refinement, where both kinds of patch take the limit
 * position of the scheme's limit masks. The grid's points are then the limit points of uniform
 * refinement to level L, and points in between are Bfr's surface with those approximation levels.
 *
 * <p>Immutable and shared by all threads; each {@link Evaluator} belongs to one thread at a time.
 * The constructor builds only a vertex-to-face incidence (linear in the mesh); an evaluator's
 * set-up costs its face's neighbourhood.
 */
public final class LimitSurface {
    /**
     * The deepest approximation level an evaluator refines to: grids up to rate 2^10 per edge
     * have their points at vertices of the refinement; finer grids are still on Bfr's surface
     * with approximation levels 10, 10.
     */
    public static final int MAX_LEVEL = 10;
    /** Bfr's default approximation levels for smooth and for sharp irregular features. */
    public static final int DEFAULT_SMOOTH_LEVEL = 2, DEFAULT_SHARP_LEVEL = 6;

    private final ControlMesh control;
    /** The one-ring of a face, for its adaptive refinement (not the whole mesh's). */
    private final PatchRefiner rings;

    /**
     * The limit surface of a control mesh.
     *
     * @param control the control mesh
     * @throws IllegalArgumentException if a vertex is shared by more than
     *                                  {@link PatchRefiner#MAX_VERTEX_FACES} faces (as for adaptive tessellation)
     */
    public LimitSurface(ControlMesh control) {
        this(new PatchRefiner(control));
    }

    /**
     * The limit surface of a refiner's control mesh, sharing the refiner (which adaptive
     * tessellation keeps anyway) for the faces' one-rings.
     *
     * @param refiner the per-face refiner of the control mesh
     */
    public LimitSurface(PatchRefiner refiner) {
        this.control = refiner.control();
        this.rings = refiner;
    }

    /**
     * A new evaluator of face f's texture coordinates on its face-varying limit surface (Bfr's
     * face-varying surface, with the approximation levels of {@link #evaluator}).
     *
     * @param f a face that is not a hole, of a mesh with UVs
     * @param level as for {@link #evaluator}
     * @return the evaluator, for one thread at a time
     * @throws IllegalArgumentException for a hole, a face out of range or a mesh without UVs
     */
    public UvEvaluator uvEvaluator(int f, int level) {
        checkFace(f);
        if (control.uvs() == null) throw new IllegalArgumentException("the mesh has no UVs");
        int smooth = Math.min(MAX_LEVEL, Math.max(DEFAULT_SMOOTH_LEVEL, level));
        int sharp = Math.min(MAX_LEVEL, Math.max(DEFAULT_SHARP_LEVEL, level));
        return new UvEvaluator(FaceVaryingSurface.of(rings, f, smooth, sharp));
    }

    /** One face's texture coordinates on its face-varying limit surface; one thread at a time, allocation-free once warm. */
    public static final class UvEvaluator {
        private final FaceVaryingSurface surface;

        UvEvaluator(FaceVaryingSurface surface) { this.surface = surface; }

        /**
         * The texture coordinates at the face's (u, v).
         *
         * @param u the face parameter u
         * @param v the face parameter v
         * @param out receives (u, v) of the texture
         * @return false, with {@code out} untouched, where the surface is not evaluated
         */
        public boolean evaluate(double u, double v, double[] out) { return surface.evaluate(u, v, out); }
    }

    /** {@return the control mesh} */
    public ControlMesh control() { return control; }

    /**
     * The approximation level a face needs for grids whose largest edge rate is maxRate:
     * ceil(log2(maxRate)), at least 0.
     *
     * @param maxRate the largest edge rate of the face's grid
     * @return the level
     */
    public static int levelForRate(int maxRate) {
        return maxRate <= 1 ? 0 : 32 - Integer.numberOfLeadingZeros(maxRate - 1);
    }

    /**
     * Columns of Bfr's layout of an N-gon's quad sub-faces.
     *
     * @param n the face size (other than 4, or 3 with Loop)
     * @return the columns
     */
    public static int subFaceColumns(int n) { return FaceSurface.subFaceColumns(n); }

    /**
     * Whether face f has a limit surface (it is not a hole).
     *
     * @param f the face
     * @return false for a hole
     */
    public boolean hasSurface(int f) {
        checkFace(f);
        return !rings.isHole(f);
    }

    /**
     * Box (min x, y, z, max x, y, z) of face f's one-ring control points, which holds its limit
     * surface: the fallback where {@link Evaluator#bounds} knows nothing tighter. Not padded.
     *
     * @param f the face
     * @param out receives the six numbers
     */
    public void oneRingBounds(int f, double[] out) {
        checkFace(f);
        rings.oneRingBounds(f, out);
    }

    /**
     * A new evaluator of face f (not a hole) whose grid points at rate 2^level are vertices of its
     * refinement: Bfr's approximation levels smooth = max(2, level), sharp = max(6, level), both
     * at most {@link #MAX_LEVEL}. Regular and bilinear faces are a single patch, made from the
     * control points around the face; irregular faces refine their one-ring lazily, where
     * evaluations first fall. Thread-safe; the evaluator is not.
     *
     * @param f the face
     * @param level the level of the grid rates (0 or more; {@link #levelForRate})
     * @return the evaluator
     * @throws IllegalArgumentException for a hole, a face out of range or a negative level
     */
    public Evaluator evaluator(int f, int level) {
        checkFace(f);
        if (level < 0) throw new IllegalArgumentException("level " + level + " is negative");
        if (rings.isHole(f)) throw new IllegalArgumentException("face " + f + " is a hole: it has no limit surface");
        int smooth = Math.min(MAX_LEVEL, Math.max(DEFAULT_SMOOTH_LEVEL, level));
        int sharp = Math.min(MAX_LEVEL, Math.max(DEFAULT_SHARP_LEVEL, level));
        Level base = control.base;
        SubdivOptions options = control.options();
        if (options.scheme() == SubdivOptions.Scheme.BILINEAR || FaceSurface.isRegular(base, options, f)) {
            double[] ring = new double[6];
            rings.oneRingBounds(f, ring);
            return new Evaluator(f, FaceSurface.of(control, f), null, ring);
        }
        PatchRefiner.Local local = rings.local(f);
        return new Evaluator(f, null, AdaptiveFaceSurface.of(local.mesh(), local.face(), smooth, sharp, Math.min(level, smooth)), null);
    }

    private void checkFace(int f) {
        if (f < 0 || f >= control.faceCount()) throw new IllegalArgumentException("face " + f + " is not in the mesh (" + control.faceCount() + " faces)");
    }

    /**
     * The limit surface of one face: position and derivatives at any (u,v), and conservative
     * boxes of parameter ranges. One thread at a time (it keeps scratch space, and an irregular
     * face keeps the refinement made so far); allocates nothing per call once the sub-faces a
     * grid falls in have been refined.
     */
    public static final class Evaluator {
        private final int face;
        private final FaceSurface patch;
        private final AdaptiveFaceSurface adaptive;
        /** Scratch space of {@link #bounds}. */
        private final double[] scratch;
        /**
         * A single patch's one-ring box, widened as the patch's boxes are: it holds the limit
         * surface too, and cuts a box-spline range's box (whose rectangle may reach beyond the
         * triangle) down.
         */
        private final double[] ring;

        private Evaluator(int face, FaceSurface patch, AdaptiveFaceSurface adaptive, double[] ring) {
            this.face = face;
            this.patch = patch;
            this.adaptive = adaptive;
            this.scratch = patch == null ? null : new double[FaceSurface.BOUNDS_SCRATCH];
            if (ring != null) {
                double magnitude = 0;
                for (double x : ring) magnitude = Math.max(magnitude, Math.abs(x));
                double pad = FaceSurface.BOUNDS_ULPS * Math.ulp(magnitude);
                for (int k = 0; k < 3; k++) {
                    ring[k] -= pad;
                    ring[k + 3] += pad;
                }
            }
            this.ring = ring;
        }

        /** {@return the face} */
        public int face() { return face; }

        /**
         * Whether the face is a single polynomial patch (regular B-spline or box-spline, or
         * bilinear) rather than adaptively refined.
         *
         * @return true for a single patch
         */
        public boolean isRegular() { return patch != null; }

        /**
         * Position and first derivatives (in the face's parameterization) at (u,v); any output
         * may be null, each takes 3 values.
         *
         * @param u the first parameter
         * @param v the second parameter
         * @param position receives x, y, z, or null
         * @param du receives the derivative in u, or null
         * @param dv receives the derivative in v, or null
         * @return false (outputs untouched) where the surface is not evaluated: an end patch
         *         whose corner Far's end patches do not handle
         * @throws IllegalArgumentException if (u,v) is outside the face's parameters
         */
        public boolean evaluate(double u, double v, double[] position, double[] du, double[] dv) {
            if (patch != null) {
                patch.evaluate(u, v, position, du, dv);
                return true;
            }
            return adaptive.evaluate(u, v, position, du, dv);
        }

        /**
         * A conservative box (min x, y, z, max x, y, z into out[0..5]) of the limit surface over
         * the face parameters [u0,u1] x [v0,v1] (within one sub-face for N-gons; the part of it
         * inside a Loop triangle), or false when no box tighter than the face's one-ring hull
         * ({@link LimitSurface#oneRingBounds}) is known. Regular B-spline quads: the box of the
         * sub-range's Bezier control points (the patch lies in their convex hull); bilinear: of
         * the range's corners; regular Loop triangles: of the Bernstein coefficients of the
         * box-spline polynomial over the rectangle, cut down to the one-ring's box. Irregular faces: false. Widened by a few
         * hundred ulps of the coordinates' magnitude, well above the rounding of both the box and
         * {@link #evaluate}, so a piece whose box misses a ray may be skipped.
         *
         * @param u0 the range's least u
         * @param u1 its greatest u (at least u0)
         * @param v0 the range's least v
         * @param v1 its greatest v (at least v0)
         * @param out receives the box
         * @return true if a box was written
         */
        public boolean bounds(double u0, double u1, double v0, double v1, double[] out) {
            if (!(u0 <= u1 && v0 <= v1)) throw new IllegalArgumentException("empty range [" + u0 + ", " + u1 + "] x [" + v0 + ", " + v1 + "]");
            if (patch == null) return false;
            patch.bounds(u0, u1, v0, v1, out, scratch);
            for (int k = 0; k < 3; k++) {
                out[k] = Math.max(out[k], ring[k]);
                out[k + 3] = Math.min(out[k + 3], ring[k + 3]);
            }
            return true;
        }

        /** The adaptive evaluator's patches so far (0 for a single patch), for benchmarks. */
        int patchCount() { return adaptive == null ? 0 : adaptive.patchCount(); }
    }
}
