package lt.spindulys.scene;

import lt.spindulys.trace.ShadingData;

/**
 * Shading data of a hit on indexed triangles: the geometric normal, the interpolated (smooth) or
 * facet (flat) shading normal, and texture coordinates with their surface derivatives. Works on
 * the arrays, not on a mesh object, so that a triangle mesh and the lazily refined patches of a
 * subdivision surface shade their triangles by the one rule.
 */
final class TriangleShading {
    private TriangleShading() {}

    /**
     * Fills {@code sd} for barycentrics (u, v) on triangle {@code prim}: three position indices
     * per triangle in {@code tri}; {@code triNormal}/{@code normals} per-corner normals (null, or
     * -1 where a triangle has none: then {@code vertexNormals}, indexed like the positions); the
     * same for texture coordinates.
     */
    static void shade(int[] tri, double[] pos, boolean smooth, int[] triNormal, double[] normals, double[] vertexNormals,
                      int[] triUv, double[] uvs, int prim, double u, double v, ShadingData sd) {
        int i3 = 3 * prim;
        double[] c = sd.corners;
        for (int k = 0; k < 3; k++) System.arraycopy(pos, 3 * tri[i3 + k], c, 3 * k, 3);
        boolean hasNormals = false;
        if (smooth) {
            if (triNormal != null && triNormal[i3] >= 0) {
                for (int k = 0; k < 3; k++) System.arraycopy(normals, 3 * triNormal[i3 + k], c, NORMALS + 3 * k, 3);
                hasNormals = true;
            } else if (vertexNormals != null) {
                for (int k = 0; k < 3; k++) System.arraycopy(vertexNormals, 3 * tri[i3 + k], c, NORMALS + 3 * k, 3);
                hasNormals = true;
            }
        }
        boolean hasUv = triUv != null && triUv[i3] >= 0;
        if (hasUv) for (int k = 0; k < 3; k++) System.arraycopy(uvs, 2 * triUv[i3 + k], c, UVS + 2 * k, 2);
        shadeCorners(smooth && hasNormals, hasUv, u, v, sd);
    }

    /**
     * Hanika's shadow-terminator offset ("Hacking the shadow terminator", Ray Tracing Gems II):
     * the barycentric point p is projected onto each corner's tangent plane, where it lies below
     * it, and the projections blended by the barycentrics: p' = p - sum b_i min(0, (p - p_i).n_i) n_i.
     * Where the vertex normals describe a convex surface this lifts p towards it; where they
     * describe a concave or flat one p stays. Leaves the object-space offset p' - p in
     * {@link ShadingData#shadowOrigin} and sets {@link ShadingData#lifted} when it is not zero.
     *
     * <p>Two guards keep the point out of the solid where the normals are not those of a smooth
     * surface: a corner whose normal faces away from the triangle's own (at a crease, a corner may
     * carry the neighbouring face's normal, at right angles) adds nothing, and a lift that would
     * take the point below the triangle's plane keeps only its part within the plane.
     *
     * @param sign +1, or -1 where the vertex normals point against the triangle's winding (they
     *             are turned to the geometric normal's side, as the shading normal is)
     * @param gx the triangle's geometric normal (any length), x; likewise gy, gz
     */
    static void liftShadowOrigin(double sign, double gx, double gy, double gz, double b0, double b1, double b2, ShadingData sd) {
        double[] c = sd.corners;
        double px = b0 * c[0] + b1 * c[3] + b2 * c[6];
        double py = b0 * c[1] + b1 * c[4] + b2 * c[7];
        double pz = b0 * c[2] + b1 * c[5] + b2 * c[8];
        double ox = 0, oy = 0, oz = 0;
        for (int k = 0; k < 3; k++) {
            int q = 3 * k, n = NORMALS + q;
            double nx = c[n], ny = c[n + 1], nz = c[n + 2];
            double len2 = nx * nx + ny * ny + nz * nz;
            if (!(len2 > 0) || !Double.isFinite(len2)) return;
            // Normals in a mesh file need not be unit; the projection needs them to be.
            double inv = sign / Math.sqrt(len2);
            nx *= inv; ny *= inv; nz *= inv;
            if (nx * gx + ny * gy + nz * gz <= 0) continue;
            double d = (px - c[q]) * nx + (py - c[q + 1]) * ny + (pz - c[q + 2]) * nz;
            if (d < 0) {
                double w = (k == 0 ? b0 : k == 1 ? b1 : b2) * d;
                ox -= w * nx; oy -= w * ny; oz -= w * nz;
            }
        }
        double down = ox * gx + oy * gy + oz * gz;
        if (down < 0) {
            double k = down / (gx * gx + gy * gy + gz * gz);
            ox -= k * gx; oy -= k * gy; oz -= k * gz;
        }
        if (ox == 0 && oy == 0 && oz == 0) return;
        sd.shadowOrigin[0] = ox; sd.shadowOrigin[1] = oy; sd.shadowOrigin[2] = oz;
        sd.lifted = true;
    }

    /** Where {@link ShadingData#corners} holds the corners' normals (9 values) and uvs (6), after the positions (9). */
    static final int NORMALS = 9, UVS = 18;

    /**
     * Fills {@code sd} for barycentrics (u, v) on the triangle whose corners are in
     * {@link ShadingData#corners}: positions a, b, c, then (if {@code smooth}) their normals at
     * {@link #NORMALS}, then (if {@code hasUv}) their texture coordinates at {@link #UVS}.
     */
    static void shadeCorners(boolean smooth, boolean hasUv, double u, double v, ShadingData sd) {
        double[] p = sd.corners;
        final int a = 0, b = 3, c = 6;
        double b1 = u, b2 = v, b0 = 1 - b1 - b2;
        double e1x = p[b] - p[a], e1y = p[b + 1] - p[a + 1], e1z = p[b + 2] - p[a + 2];
        double e2x = p[c] - p[a], e2y = p[c + 1] - p[a + 1], e2z = p[c + 2] - p[a + 2];
        double gx = e1y * e2z - e1z * e2y, gy = e1z * e2x - e1x * e2z, gz = e1x * e2y - e1y * e2x;
        sd.ng[0] = gx; sd.ng[1] = gy; sd.ng[2] = gz;
        double sx = gx, sy = gy, sz = gz;
        if (smooth) {
            final int na = NORMALS, nb = NORMALS + 3, nc = NORMALS + 6;
            double nx = b0 * p[na] + b1 * p[nb] + b2 * p[nc];
            double ny = b0 * p[na + 1] + b1 * p[nb + 1] + b2 * p[nc + 1];
            double nz = b0 * p[na + 2] + b1 * p[nb + 2] + b2 * p[nc + 2];
            double len2 = nx * nx + ny * ny + nz * nz;
            if (len2 > 0 && Double.isFinite(len2)) {
                // Interpolated normals may disagree with the winding; keep them on the outward side.
                double s = nx * gx + ny * gy + nz * gz < 0 ? -1 : 1;
                sx = s * nx; sy = s * ny; sz = s * nz;
                liftShadowOrigin(s, gx, gy, gz, b0, b1, b2, sd);
            }
        }
        sd.ns[0] = sx; sd.ns[1] = sy; sd.ns[2] = sz;
        if (!sd.needsParameters) return;

        if (hasUv) {
            final int ta = UVS, tb = UVS + 2, tc = UVS + 4;
            double u0 = p[ta], v0 = p[ta + 1], u1 = p[tb], v1 = p[tb + 1], u2 = p[tc], v2 = p[tc + 1];
            sd.u = b0 * u0 + b1 * u1 + b2 * u2;
            sd.v = b0 * v0 + b1 * v1 + b2 * v2;
            // Solve p = p2 + (u - u2) dpdu + (v - v2) dpdv on the two edges meeting at corner 2.
            double du02 = u0 - u2, dv02 = v0 - v2, du12 = u1 - u2, dv12 = v1 - v2;
            double det = du02 * dv12 - dv02 * du12;
            if (Math.abs(det) > 1e-12 * (Math.abs(du02 * dv12) + Math.abs(dv02 * du12)) && Double.isFinite(1 / det)) {
                double inv = 1 / det;
                double p02x = p[a] - p[c], p02y = p[a + 1] - p[c + 1], p02z = p[a + 2] - p[c + 2];
                double p12x = p[b] - p[c], p12y = p[b + 1] - p[c + 1], p12z = p[b + 2] - p[c + 2];
                sd.setDerivatives((dv12 * p02x - dv02 * p12x) * inv, (dv12 * p02y - dv02 * p12y) * inv, (dv12 * p02z - dv02 * p12z) * inv,
                        (du02 * p12x - du12 * p02x) * inv, (du02 * p12y - du12 * p02y) * inv, (du02 * p12z - du12 * p02z) * inv);
                return;
            }
        } else {
            sd.u = b1;
            sd.v = b2;
        }
        // Without a usable uv map the barycentrics are the parametrisation: p = a + u e1 + v e2.
        sd.setDerivatives(e1x, e1y, e1z, e2x, e2y, e2z);
    }
}
