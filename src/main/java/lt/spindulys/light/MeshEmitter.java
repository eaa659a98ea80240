package lt.spindulys.light;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.material.Material;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.TriangleMesh;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.TexturePoint;
import lt.spindulys.texture.Uniform;

/**
 * The emissive triangles of a mesh as a light for path tracing: a material's {@code emission}, or
 * an OBJ {@code Ke}, that is the same all over each triangle. A point is drawn by picking a
 * triangle in proportion to its area times its brightness (the mean of its radiance's channels)
 * and then uniformly on it, so the density per unit area of a point on triangle k is
 * brightness_k / W, W the sum of area times brightness. The triangles emit from both faces, as
 * the surface is seen from either side.
 *
 * <p>Only meshes that hold still (no motion blur) and stand alone (not a CSG operand, whose
 * surface the operation may cut away) are made lights; light from other emissive surfaces is
 * found by the paths that hit them. The triangles' world-space corners are copied once, under a
 * heap reservation. Immutable.
 */
public final class MeshEmitter extends Light {
    private final TriangleMesh mesh;
    /** World-space corners of the emissive triangles: 9 per triangle. */
    private final double[] corners;
    /** Radiance of each emissive triangle: 3 per triangle. */
    private final double[] radiance;
    /** Running sums of area times brightness, normalised: the last is 1. */
    private final double[] cumulative;
    /** Unit normals of the emissive triangles: 3 per triangle. */
    private final double[] normals;
    private final double[] areas;
    /** The sum of area times brightness over the emissive triangles. */
    private final double weight;
    /** The distinct materials of the emissive triangles: a hit on the mesh with another material was not sampled. */
    private final Material[] materials;

    private MeshEmitter(TriangleMesh mesh, double[] corners, double[] radiance, double[] normals, double[] areas, double[] cumulative,
                        double weight, Material[] materials) {
        super(1, false);
        this.mesh = mesh;
        this.materials = materials;
        this.corners = corners;
        this.radiance = radiance;
        this.normals = normals;
        this.areas = areas;
        this.cumulative = cumulative;
        this.weight = weight;
    }

    /** Heap held per emissive triangle: corners, radiance, normal, area and running sum, with the arrays' headers amortised. */
    static final long BYTES_PER_TRIANGLE = (9 + 3 + 3 + 1 + 1) * 8L;

    /**
     * The emissive triangles of {@code mesh} as a light, or null if none of its triangles emits
     * a uniform radiance, or if the mesh moves or is part of a CSG solid.
     *
     * @param mesh the mesh, frozen
     * @return the light, or null
     * @throws lt.spindulys.limits.InsufficientMemoryException if the heap cannot hold the copies
     */
    static MeshEmitter of(TriangleMesh mesh) {
        if (mesh.isMoving() || mesh.solid() != mesh) return null;
        double[] rgb = new double[3];
        TexturePoint point = new TexturePoint();
        // Most meshes glow nowhere: their few materials say so without a pass over the triangles.
        boolean[] glows = {false};
        mesh.forEachMaterial(m -> glows[0] |= uniformEmission(m, point, rgb) && brightness(rgb) > 0);
        if (!glows[0]) return null;
        int n = mesh.triangleCount();
        int count = 0;
        for (int t = 0; t < n; t++) if (uniformEmission(mesh.material(t, 0), point, rgb) && brightness(rgb) > 0) count++;
        if (count == 0) return null;
        try (HeapBudget.Reservation r = HeapBudget.reserve(count * BYTES_PER_TRIANGLE,
                "the " + count + " emissive triangles of " + mesh.name() + " as a light")) {
            Transform toWorld = mesh.objectToWorld(0);
            double[] corners = new double[9 * count], radiance = new double[3 * count], normals = new double[3 * count];
            double[] areas = new double[count], cumulative = new double[count];
            double[] local = new double[9];
            double sum = 0;
            int k = 0;
            java.util.Set<Material> sampled = java.util.Collections.newSetFromMap(new java.util.IdentityHashMap<>());
            for (int t = 0; t < n; t++) {
                if (!uniformEmission(mesh.material(t, 0), point, rgb) || !(brightness(rgb) > 0)) continue;
                sampled.add(mesh.material(t, 0));
                mesh.corners(t, local);
                for (int c = 0; c < 3; c++) {
                    Vec3 w = toWorld.point(new Vec3(local[3 * c], local[3 * c + 1], local[3 * c + 2]));
                    corners[9 * k + 3 * c] = w.x(); corners[9 * k + 3 * c + 1] = w.y(); corners[9 * k + 3 * c + 2] = w.z();
                }
                double ex = corners[9 * k + 3] - corners[9 * k], ey = corners[9 * k + 4] - corners[9 * k + 1], ez = corners[9 * k + 5] - corners[9 * k + 2];
                double fx = corners[9 * k + 6] - corners[9 * k], fy = corners[9 * k + 7] - corners[9 * k + 1], fz = corners[9 * k + 8] - corners[9 * k + 2];
                double nx = ey * fz - ez * fy, ny = ez * fx - ex * fz, nz = ex * fy - ey * fx;
                double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
                double area = len / 2;
                if (len > 0) { nx /= len; ny /= len; nz /= len; }
                normals[3 * k] = nx; normals[3 * k + 1] = ny; normals[3 * k + 2] = nz;
                areas[k] = area;
                radiance[3 * k] = rgb[0]; radiance[3 * k + 1] = rgb[1]; radiance[3 * k + 2] = rgb[2];
                sum += area * brightness(rgb);
                cumulative[k] = sum;
                k++;
            }
            if (!(sum > 0)) return null; // every emissive triangle degenerate
            for (int i = 0; i < count; i++) cumulative[i] /= sum;
            cumulative[count - 1] = 1;
            return new MeshEmitter(mesh, corners, radiance, normals, areas, cumulative, sum, sampled.toArray(new Material[0]));
        }
    }

    /**
     * Writes the radiance a material emits to rgb when it is the same all over a surface (its
     * {@code emission} plus a {@link Uniform} emission texture, if any), and returns true; false
     * when a texture varies it.
     */
    static boolean uniformEmission(Material m, TexturePoint point, double[] rgb) {
        rgb[0] = m.emission().r(); rgb[1] = m.emission().g(); rgb[2] = m.emission().b();
        var texture = m.texture(Channel.EMISSION);
        if (texture == null) return true;
        if (!(texture instanceof Uniform)) return false;
        double r = rgb[0], g = rgb[1], b = rgb[2];
        texture.evaluate(point, rgb);
        rgb[0] += r; rgb[1] += g; rgb[2] += b;
        return true;
    }

    /** The scalar by which triangles are picked and densities are measured: the mean of the channels. */
    static double brightness(double[] rgb) { return (rgb[0] + rgb[1] + rgb[2]) / 3; }

    /**
     * Whether the triangles of material m are among the ones this light samples: a hit on the
     * mesh is weighed against the light's density only then (a triangle whose emission a texture
     * varies is found by paths alone).
     *
     * @param m the material at a hit on the mesh
     * @return true if its triangles are sampled
     */
    public boolean samples(Material m) {
        for (Material x : materials) if (x == m) return true;
        return false;
    }

    /**
     * The mesh whose triangles these are.
     *
     * @return the mesh
     */
    public TriangleMesh mesh() { return mesh; }

    @Override
    public boolean sampleLi(double px, double py, double pz, double u, double v, LightSample out) {
        int lo = 0, hi = cumulative.length - 1;
        while (lo < hi) { // the first triangle whose running sum exceeds u
            int mid = (lo + hi) >>> 1;
            if (cumulative[mid] > u) hi = mid; else lo = mid + 1;
        }
        int k = lo;
        double below = k == 0 ? 0 : cumulative[k - 1];
        double span = cumulative[k] - below;
        double uu = span > 0 ? Math.min((u - below) / span, Math.nextDown(1.0)) : 0.5;
        // Uniform on the triangle: barycentrics from the square root warp.
        double su = Math.sqrt(uu), b1 = 1 - su, b2 = v * su, b0 = 1 - b1 - b2;
        int c = 9 * k;
        double x = b0 * corners[c] + b1 * corners[c + 3] + b2 * corners[c + 6];
        double y = b0 * corners[c + 1] + b1 * corners[c + 4] + b2 * corners[c + 7];
        double z = b0 * corners[c + 2] + b1 * corners[c + 5] + b2 * corners[c + 8];
        double lx = x - px, ly = y - py, lz = z - pz;
        double d2 = lx * lx + ly * ly + lz * lz;
        if (!(d2 > 0)) return false;
        double d = Math.sqrt(d2);
        double wx = lx / d, wy = ly / d, wz = lz / d;
        double cos = Math.abs(wx * normals[3 * k] + wy * normals[3 * k + 1] + wz * normals[3 * k + 2]);
        if (!(cos > 0)) return false;
        double r = radiance[3 * k], g = radiance[3 * k + 1], b = radiance[3 * k + 2];
        out.wx = wx; out.wy = wy; out.wz = wz;
        out.distance = d;
        out.x = x; out.y = y; out.z = z;
        out.shadowTMax = PlanarSource.SURFACE_T_MAX;
        out.r = r; out.g = g; out.b = b;
        out.pdf = pdfAt(brightness(r, g, b), d2, cos);
        out.delta = false;
        double share = 1 / out.pdf;
        out.weightedR = r * share; out.weightedG = g * share; out.weightedB = b * share;
        return true;
    }

    private static double brightness(double r, double g, double b) { return (r + g + b) / 3; }

    /**
     * The density in solid angle of a point that the light draws, on a triangle of this
     * brightness, at squared distance d2 from the shaded point and seen at cosine cos from the
     * triangle's normal: what a path that hits the mesh there weighs its light against.
     *
     * @param brightness the mean of the radiance's channels at the point
     * @param d2         the squared distance
     * @param cos        |cos| at the light
     * @return the pdf per steradian
     */
    public double pdfAt(double brightness, double d2, double cos) {
        return brightness / weight * d2 / cos;
    }

    /**
     * The density of direction w from the point, found by testing every emissive triangle (the
     * nearest crossing counts): linear in the triangles, for tests and rare callers. A path
     * tracer that has hit the mesh uses {@link #pdfAt} instead.
     */
    @Override
    public double pdfLi(double px, double py, double pz, double wx, double wy, double wz) {
        double best = Double.POSITIVE_INFINITY;
        int seen = -1;
        for (int k = 0; k < areas.length; k++) {
            double t = crossing(k, px, py, pz, wx, wy, wz);
            if (t < best) { best = t; seen = k; }
        }
        if (seen < 0) return 0;
        double cos = Math.abs(wx * normals[3 * seen] + wy * normals[3 * seen + 1] + wz * normals[3 * seen + 2]);
        if (!(cos > 0)) return 0;
        return pdfAt(brightness(radiance[3 * seen], radiance[3 * seen + 1], radiance[3 * seen + 2]), best * best, cos);
    }

    /** Where the ray from p along unit w crosses triangle k (Moller-Trumbore), or +Infinity. */
    private double crossing(int k, double px, double py, double pz, double wx, double wy, double wz) {
        int c = 9 * k;
        double ax = corners[c], ay = corners[c + 1], az = corners[c + 2];
        double e1x = corners[c + 3] - ax, e1y = corners[c + 4] - ay, e1z = corners[c + 5] - az;
        double e2x = corners[c + 6] - ax, e2y = corners[c + 7] - ay, e2z = corners[c + 8] - az;
        double qx = wy * e2z - wz * e2y, qy = wz * e2x - wx * e2z, qz = wx * e2y - wy * e2x;
        double det = e1x * qx + e1y * qy + e1z * qz;
        if (det == 0) return Double.POSITIVE_INFINITY;
        double inv = 1 / det;
        double sx = px - ax, sy = py - ay, sz = pz - az;
        double bu = (sx * qx + sy * qy + sz * qz) * inv;
        if (bu < 0 || bu > 1) return Double.POSITIVE_INFINITY;
        double rx = sy * e1z - sz * e1y, ry = sz * e1x - sx * e1z, rz = sx * e1y - sy * e1x;
        double bv = (wx * rx + wy * ry + wz * rz) * inv;
        if (bv < 0 || bu + bv > 1) return Double.POSITIVE_INFINITY;
        double t = (e2x * rx + e2y * ry + e2z * rz) * inv;
        return t > 0 ? t : Double.POSITIVE_INFINITY;
    }

    @Override
    public String statement() { return "mesh"; }
}
