package lt.spindulys.subdiv;

/**
 * The limit surface of a control mesh evaluated directly at face parameters (temporary wiring
 * version; replaced by the evaluator branch).
 */
public final class LimitSurface {
    private final ControlMesh control;

    private final PatchRefiner refiner;

    public LimitSurface(ControlMesh control) { this.control = control; this.refiner = null; }

    public LimitSurface(PatchRefiner refiner) { this.control = refiner.control(); this.refiner = refiner; }

    public ControlMesh control() { return control; }

    public static int levelForRate(int maxRate) {
        return maxRate <= 1 ? 0 : 32 - Integer.numberOfLeadingZeros(maxRate - 1);
    }

    public Evaluator evaluator(int f, int level) {
        SubdivOptions o = control.options();
        if (o.scheme() == SubdivOptions.Scheme.BILINEAR || FaceSurface.isRegular(control.base, o, f)) {
            return new Evaluator(f, FaceSurface.of(control, f), null);
        }
        return new Evaluator(f, null, AdaptiveFaceSurface.of(control, f, Math.min(10, Math.max(2, level)), Math.min(10, Math.max(6, level))));
    }

    public static int subFaceColumns(int n) { return FaceSurface.subFaceColumns(n); }

    public UvEvaluator uvEvaluator(int f, int level) {
        FaceVaryingSurface s = refiner != null ? FaceVaryingSurface.of(refiner, f, Math.min(10, Math.max(2, level)), Math.min(10, Math.max(6, level)))
                : FaceVaryingSurface.of(control, f, Math.min(10, Math.max(2, level)), Math.min(10, Math.max(6, level)));
        return new UvEvaluator(s);
    }

    /** One face's texture coordinates on its face-varying limit surface; one thread at a time. */
    public static final class UvEvaluator {
        private final FaceVaryingSurface surface;

        UvEvaluator(FaceVaryingSurface surface) { this.surface = surface; }

        /** The (u, v) texture coordinates at the face's parameters into out[0..1]; false where not evaluated. */
        public boolean evaluate(double u, double v, double[] out) { return surface.evaluate(u, v, out); }
    }

    /** One face's evaluator; one thread at a time. */
    public static final class Evaluator {
        private final int face;
        private final FaceSurface regular;
        private final AdaptiveFaceSurface adaptive;

        Evaluator(int face, FaceSurface regular, AdaptiveFaceSurface adaptive) {
            this.face = face;
            this.regular = regular;
            this.adaptive = adaptive;
        }

        public int face() { return face; }

        public boolean isRegular() { return regular != null; }

        public boolean evaluate(double u, double v, double[] position, double[] du, double[] dv) {
            if (regular != null) {
                regular.evaluate(u, v, position, du, dv);
                return true;
            }
            return adaptive.evaluate(u, v, position, du, dv);
        }

        public boolean bounds(double u0, double u1, double v0, double v1, double[] out) { return false; }
    }
}
