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
        int a = 3 * tri[i3], b = 3 * tri[i3 + 1], c = 3 * tri[i3 + 2];
        double b1 = u, b2 = v, b0 = 1 - b1 - b2;
        double e1x = pos[b] - pos[a], e1y = pos[b + 1] - pos[a + 1], e1z = pos[b + 2] - pos[a + 2];
        double e2x = pos[c] - pos[a], e2y = pos[c + 1] - pos[a + 1], e2z = pos[c + 2] - pos[a + 2];
        double gx = e1y * e2z - e1z * e2y, gy = e1z * e2x - e1x * e2z, gz = e1x * e2y - e1y * e2x;
        sd.ng[0] = gx; sd.ng[1] = gy; sd.ng[2] = gz;
        double sx = gx, sy = gy, sz = gz;
        if (smooth) {
            double[] src;
            int na, nb, nc;
            if (triNormal != null && triNormal[i3] >= 0) {
                src = normals;
                na = 3 * triNormal[i3]; nb = 3 * triNormal[i3 + 1]; nc = 3 * triNormal[i3 + 2];
            } else {
                src = vertexNormals;
                na = a; nb = b; nc = c;
            }
            double nx = b0 * src[na] + b1 * src[nb] + b2 * src[nc];
            double ny = b0 * src[na + 1] + b1 * src[nb + 1] + b2 * src[nc + 1];
            double nz = b0 * src[na + 2] + b1 * src[nb + 2] + b2 * src[nc + 2];
            double len2 = nx * nx + ny * ny + nz * nz;
            if (len2 > 0 && Double.isFinite(len2)) {
                // Interpolated normals may disagree with the winding; keep them on the outward side.
                double s = nx * gx + ny * gy + nz * gz < 0 ? -1 : 1;
                sx = s * nx; sy = s * ny; sz = s * nz;
            }
        }
        sd.ns[0] = sx; sd.ns[1] = sy; sd.ns[2] = sz;
        if (!sd.needsParameters) return;

        if (triUv != null && triUv[i3] >= 0) {
            int ta = 2 * triUv[i3], tb = 2 * triUv[i3 + 1], tc = 2 * triUv[i3 + 2];
            double u0 = uvs[ta], v0 = uvs[ta + 1], u1 = uvs[tb], v1 = uvs[tb + 1], u2 = uvs[tc], v2 = uvs[tc + 1];
            sd.u = b0 * u0 + b1 * u1 + b2 * u2;
            sd.v = b0 * v0 + b1 * v1 + b2 * v2;
            // Solve p = p2 + (u - u2) dpdu + (v - v2) dpdv on the two edges meeting at corner 2.
            double du02 = u0 - u2, dv02 = v0 - v2, du12 = u1 - u2, dv12 = v1 - v2;
            double det = du02 * dv12 - dv02 * du12;
            if (Math.abs(det) > 1e-12 * (Math.abs(du02 * dv12) + Math.abs(dv02 * du12)) && Double.isFinite(1 / det)) {
                double inv = 1 / det;
                double p02x = pos[a] - pos[c], p02y = pos[a + 1] - pos[c + 1], p02z = pos[a + 2] - pos[c + 2];
                double p12x = pos[b] - pos[c], p12y = pos[b + 1] - pos[c + 1], p12z = pos[b + 2] - pos[c + 2];
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
