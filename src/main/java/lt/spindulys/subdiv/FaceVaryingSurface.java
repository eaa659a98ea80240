package lt.spindulys.subdiv;

/**
 * The face-varying (UV) limit surface of one face, evaluated directly at the face's parameters
 * (Bfr's, see {@link FaceSurface}) as OpenSubdiv's {@code Bfr::SurfaceFactory::InitFaceVaryingSurface}
 * builds it: the limit surface of the UV value mesh ({@link FaceVarying}: seams are boundaries,
 * the {@link SubdivOptions.FaceVarying} option pins values as infinitely sharp corners), with the
 * UVs as its points.
 *
 * <p>A linear channel (option {@code ALL}, or the bilinear scheme) is the face's corner UVs
 * interpolated bilinearly (Loop triangles linearly, other faces per quad sub-face), taken
 * straight from the face: no refinement. Any other channel goes down
 * {@link AdaptiveFaceSurface#ofFaceVarying}'s descent, the one the positions use, on the value
 * mesh of the face's one-ring.
 *
 * <p>Set-up cost: {@link #of(PatchRefiner, int, int, int)} costs the face's one-ring (the
 * {@link PatchRefiner}, made once per control mesh, finds it); {@link #of(ControlMesh, int, int, int)}
 * is for a mesh that is already small (its first refinement, made at the first evaluation, is
 * of the whole mesh), except for linear channels, where it costs the face alone. An evaluator
 * has scratch space and a tree of its own: one thread at a time.
 */
final class FaceVaryingSurface {
    /** The descent of a smooth channel, or null for a linear one (or a hole). */
    private final AdaptiveFaceSurface adaptive;
    /** A linear channel's patch for quads and sub-faced faces; null for Loop triangles and holes. */
    private final FaceSurface linear;
    /** A Loop triangle's corner UVs (u0, v0, u1, v1, u2, v2) under a linear channel, else null. */
    private final double[] triangle;
    private final double[] point = new double[3];

    private FaceVaryingSurface(AdaptiveFaceSurface adaptive, FaceSurface linear, double[] triangle) {
        this.adaptive = adaptive;
        this.linear = linear;
        this.triangle = triangle;
    }

    /**
     * The face-varying (UV) limit surface of face f, as Bfr's InitFaceVaryingSurface; smooth/sharp
     * are Bfr's approximation levels (2 and 6 by default). A hole has none: it evaluates nowhere.
     *
     * @param mesh the control mesh, with UVs; for a smooth channel, small (such as a face's
     *             one-ring, {@link PatchRefiner#local}): the descent refines it whole once
     * @param face a face of it
     * @param smooth the approximation level for smooth features
     * @param sharp the approximation level for sharp features
     * @return the surface
     */
    static FaceVaryingSurface of(ControlMesh mesh, int face, int smooth, int sharp) {
        FaceVarying.Channel channel = mesh.uvChannel;
        if (channel == null) throw new IllegalArgumentException("the mesh has no UVs");
        if (mesh.base.hole != null && mesh.base.hole[face]) return new FaceVaryingSurface(null, null, null);
        if (channel.linear()) return linear(mesh, face);
        return new FaceVaryingSurface(AdaptiveFaceSurface.ofFaceVarying(mesh, face, smooth, sharp), null, null);
    }

    /**
     * As {@link #of(ControlMesh, int, int, int)} for a face of any mesh, from its one-ring: the
     * set-up costs the face's neighbourhood, not the mesh.
     *
     * @param refiner the refiner of the control mesh (made once per mesh and kept by the caller)
     * @param face a face of the control mesh
     * @param smooth the approximation level for smooth features
     * @param sharp the approximation level for sharp features
     * @return the surface
     */
    static FaceVaryingSurface of(PatchRefiner refiner, int face, int smooth, int sharp) {
        ControlMesh mesh = refiner.control();
        if (mesh.uvChannel == null || mesh.uvChannel.linear() || (mesh.base.hole != null && mesh.base.hole[face])) {
            return of(mesh, face, smooth, sharp);
        }
        PatchRefiner.Local local = refiner.local(face);
        return of(local.mesh(), local.face(), smooth, sharp);
    }

    /** The linear channel's surface of a face: its corners' UVs. */
    private static FaceVaryingSurface linear(ControlMesh mesh, int face) {
        Level base = mesh.base;
        int n = base.faceSize(face), h0 = base.firstHalf(face);
        int[] uvIndex = mesh.faceUvIndices();
        double[] uvs = mesh.uvs();
        if (mesh.options().scheme() == SubdivOptions.Scheme.LOOP) {
            double[] t = new double[6];
            for (int c = 0; c < 3; c++) System.arraycopy(uvs, 2 * uvIndex[h0 + c], t, 2 * c, 2);
            return new FaceVaryingSurface(null, null, t);
        }
        double[] corners = new double[3 * n];
        for (int c = 0; c < n; c++) System.arraycopy(uvs, 2 * uvIndex[h0 + c], corners, 3 * c, 2);
        return new FaceVaryingSurface(null, FaceSurface.linear(corners), null);
    }

    /**
     * The UV at (u,v) of the face's parameterization (Bfr's).
     *
     * @param u the face's first parameter
     * @param v the face's second parameter
     * @param uv receives u and v of the texture coordinates
     * @return false, with {@code uv} untouched, where not evaluated (a hole, or an end patch not handled)
     */
    boolean evaluate(double u, double v, double[] uv) {
        if (triangle != null) {
            double w = 1 - u - v;
            uv[0] = w * triangle[0] + u * triangle[2] + v * triangle[4];
            uv[1] = w * triangle[1] + u * triangle[3] + v * triangle[5];
            return true;
        }
        if (linear != null) linear.evaluate(u, v, point, null, null);
        else if (adaptive == null || !adaptive.evaluate(u, v, point, null, null)) return false;
        uv[0] = point[0];
        uv[1] = point[1];
        return true;
    }
}
