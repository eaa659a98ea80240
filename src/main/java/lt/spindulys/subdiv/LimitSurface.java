package lt.spindulys.subdiv;

/**
 * The limit surface of a control mesh evaluated directly at face parameters (temporary wiring
 * version; replaced by the evaluator branch).
 */
public final class LimitSurface {
    private final ControlMesh control;

    public LimitSurface(ControlMesh control) { this.control = control; }

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

    public UvEvaluator uvEvaluator(int f, int level) { return new UvEvaluator(control, f); }

    /** Temporary: bilinear UVs (linear-all). */
    public static final class UvEvaluator {
        private final FaceSurface s;
        UvEvaluator(ControlMesh m, int f) {
            int n = m.faceSizes()[f];
            int start = 0;
            for (int g = 0; g < f; g++) start += m.faceSizes()[g];
            double[] cp = new double[3 * n];
            int[] fu = m.faceUvIndices();
            for (int k = 0; k < n; k++) { cp[3 * k] = m.uvs()[2 * fu[start + k]]; cp[3 * k + 1] = m.uvs()[2 * fu[start + k] + 1]; }
            s = null;
            this.cp = cp; this.n = n;
        }
        private final double[] cp; private final int n;
        public boolean evaluate(double u, double v, double[] out) {
            if (n == 4) {
                out[0] = (1 - u) * (1 - v) * cp[0] + u * (1 - v) * cp[3] + u * v * cp[6] + (1 - u) * v * cp[9];
                out[1] = (1 - u) * (1 - v) * cp[1] + u * (1 - v) * cp[4] + u * v * cp[7] + (1 - u) * v * cp[10];
            } else { out[0] = cp[0]; out[1] = cp[1]; }
            return true;
        }
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
