package lt.spindulys.bench;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import lt.spindulys.files.AtomicFile;
import lt.spindulys.math.Vec3;
import lt.spindulys.mesh.MeshData;

/**
 * What the bench gives each peer renderer for a {@link PeerView}: command lines for Embree's
 * {@code pathtracer} tutorial and Blender, the Python script Blender runs, and POV-Ray's scene
 * and {@code mesh2} include files (POV-Ray reads no OBJ). Every quad is split along v0-v2, as
 * our reader and Embree's do, so all renderers trace the same triangles.
 */
final class PeerInputs {
    private PeerInputs() {}

    /** The Python script Blender runs (a resource beside this class), written into the scratch folder. */
    static final String CYCLES_SCRIPT = "cycles_view.py";

    // ---- Embree ----

    /**
     * Embree's {@code pathtracer} on the view: 1 sample per pixel and a path length of 1 (the
     * camera ray and one shadow ray), the point light at the view's radiant intensity.
     * {@code tail} ends the line: {@code -o IMAGE.ppm} for a whole render, or
     * {@code --benchmark 1 N --legacy} for its render-only frame time.
     */
    static List<String> embree(String exe, PeerView v, int threads, List<String> tail) {
        return embree(exe, v, threads, 1, 1, tail);
    }

    /**
     * Embree's {@code pathtracer} on the view at {@code spp} samples per pixel and paths of at most
     * {@code pathLength} hits. Its loop traces one ray per hit and samples every light at each
     * (tutorials/pathtracer/pathtracer_device.cpp, renderPixelFunction), so a path length of N is our
     * maxdepth N - 1 and Cycles' max_bounces N - 1: 1 is the camera ray and its shadow rays.
     */
    static List<String> embree(String exe, PeerView v, int threads, int spp, int pathLength, List<String> tail) {
        List<String> c = new ArrayList<>(List.of(exe));
        for (Path m : v.meshes()) c.addAll(List.of("-i", m.toString()));
        c.add("--vp");
        add(c, v.eye());
        c.add("--vi");
        add(c, v.at());
        c.add("--vu");
        add(c, v.up());
        c.addAll(List.of("--fov", BenchMeshes.number(v.verticalFov()), "--righthanded",
                "--size", Integer.toString(v.width()), Integer.toString(v.height())));
        c.add("--pointlight");
        add(c, v.light());
        String i = BenchMeshes.number(v.radiantIntensity());
        c.addAll(List.of(i, i, i, "--spp", Integer.toString(spp), "--max-path-length", Integer.toString(pathLength),
                "--threads", Integer.toString(threads)));
        c.addAll(tail);
        return c;
    }

    private static void add(List<String> c, Vec3 p) {
        c.addAll(List.of(BenchMeshes.number(p.x()), BenchMeshes.number(p.y()), BenchMeshes.number(p.z())));
    }

    // ---- Blender Cycles ----

    /**
     * Blender in the background running {@link #CYCLES_SCRIPT} on the view. A Cycles point light
     * of P watts has a radiant intensity of P / (4 pi) W/sr.
     */
    static List<String> cycles(String exe, Path script, PeerView v, int threads, Path image) {
        List<String> c = new ArrayList<>(List.of(exe, "-b", "--factory-startup", "-noaudio", "-P", script.toString(), "--"));
        for (Path m : v.meshes()) c.addAll(List.of("--mesh", m.toString()));
        c.addAll(List.of("--image", image.toString(), "--threads", Integer.toString(threads),
                "--size", Integer.toString(v.width()), Integer.toString(v.height()), "--eye"));
        add(c, v.eye());
        c.add("--at");
        add(c, v.at());
        c.addAll(List.of("--vfov", BenchMeshes.number(v.verticalFov()), "--light"));
        add(c, v.light());
        c.addAll(List.of("--watts", BenchMeshes.number(4 * Math.PI * v.radiantIntensity())));
        return c;
    }

    /**
     * {@link #cycles} path tracing: {@code samples} per pixel, {@code bounces} of every kind (our
     * maxdepth), the settings of {@link #CYCLES_SCRIPT}'s {@code --bounces} (no clamp, caustics on, a
     * 1-pixel box filter, no denoising or adaptive sampling), seeded; with {@code pfm}, the linear image too.
     */
    static List<String> cyclesPath(String exe, Path script, PeerView v, int threads, Path image, int samples, int bounces, int seed,
            Path pfm) {
        List<String> c = new ArrayList<>(cycles(exe, script, v, threads, image));
        c.addAll(List.of("--samples", Integer.toString(samples), "--bounces", Integer.toString(bounces), "--seed", Integer.toString(seed)));
        if (pfm != null) c.addAll(List.of("--pfm", pfm.toString()));
        return c;
    }

    /** Writes {@link #CYCLES_SCRIPT} into {@code dir} and returns its path. */
    static Path writeCyclesScript(Path dir) throws IOException {
        Path p = dir.resolve(CYCLES_SCRIPT);
        try (InputStream in = PeerInputs.class.getResourceAsStream(CYCLES_SCRIPT)) {
            if (in == null) throw new IOException("resource " + CYCLES_SCRIPT + " is missing from the build");
            byte[] text = in.readAllBytes();
            AtomicFile.write(p, out -> out.write(text));
        }
        return p;
    }

    // ---- POV-Ray ----

    /** The POV-Ray command line for {@code scene} (in the working folder), pixel centres, no anti-aliasing, PPM out. */
    static List<String> povray(String exe, PeerView v, int threads, String scene, String image) {
        return List.of(exe, "+I" + scene, "+O" + image, "+W" + v.width(), "+H" + v.height(), "-A", "+WT" + threads, "-D", "+FP", "-V");
    }

    /**
     * The POV-Ray scene of the view, including {@code includes} (one {@link #writeMesh2 mesh2}
     * file per mesh). POV-Ray is left-handed; a negative {@code right} vector makes its camera
     * right-handed, so the OBJ coordinates are used unchanged. Its {@code angle} is the
     * horizontal field of view. Its point light with {@code fade_distance 1 fade_power 2}
     * scales by 2 / (1 + d^2) and its diffuse term has no 1/pi, so the colour that matches a
     * radiant intensity I with a Lambert BRDF is I / (2 pi) (off by d^2 / (1 + d^2), 3 % at the
     * bench lights' 5-6 units). With the view's {@link PeerView.Area area}, the light is an
     * {@code area_light} whose grid of point lights shares that colour; each sample lights as a
     * point light, without our emitter's cosine at the light, so the two agree where that cosine
     * is near 1 (beneath the light) and POV-Ray is brighter towards the sides.
     */
    static String povScene(PeerView v, List<String> includes) {
        StringBuilder s = new StringBuilder();
        s.append("// written by `render bench` (bench/PeerInputs)\n#version 3.7;\n");
        s.append("global_settings { assumed_gamma 1.0 max_trace_level 1 }\n");
        s.append("camera { perspective\n  location ").append(vector(v.eye()))
                .append("\n  right -x*").append(v.width()).append('/').append(v.height())
                .append("\n  up y\n  angle ").append(String.format(Locale.ROOT, "%.4f", v.horizontalFov()))
                .append("\n  look_at ").append(vector(v.at())).append("\n}\n");
        s.append("light_source { ").append(vector(v.light())).append(" color rgb ")
                .append(BenchMeshes.number(v.radiantIntensity() / (2 * Math.PI)));
        PeerView.Area a = v.area();
        if (a != null) {
            // jitter and adaptive 0: every sample of the grid traced, each at a random spot in its cell;
            // area_illumination: each sample shades from its own direction, as ours do (by default
            // POV-Ray shades from the centre only, and a face turned from the centre stays black).
            s.append("\n  area_light ").append(vector(a.axis1())).append(", ").append(vector(a.axis2())).append(", ")
                    .append(a.grid()).append(", ").append(a.grid()).append(" adaptive 0 jitter").append(a.disc() ? " circular" : "")
                    .append(" area_illumination on\n ");
        }
        s.append(" fade_distance 1 fade_power 2 }\n");
        s.append("#declare BenchGrey = texture { pigment { color rgb 0.8 } finish { ambient 0 diffuse 1 } }\n");
        for (String inc : includes) {
            s.append("object {\n#include \"").append(inc).append("\"\n  texture { BenchGrey } }\n");
        }
        return s.toString();
    }

    private static String vector(Vec3 p) {
        return "<" + BenchMeshes.number(p.x()) + "," + BenchMeshes.number(p.y()) + "," + BenchMeshes.number(p.z()) + ">";
    }

    /**
     * {@code m} as a POV-Ray {@code mesh2}: its positions (in the OBJ files' six-decimal format,
     * so the numbers are the ones the OBJ holds) and each face fanned from its first corner,
     * which for a quad is the v0-v2 split. No texture coordinates: the views are untextured.
     */
    static void writeMesh2(OutputStream out, MeshData m) throws IOException {
        StringBuilder sb = new StringBuilder(1 << 16);
        Spill spill = new Spill(out, sb);
        int n = m.vertexCount();
        double[] p = m.positions();
        sb.append("mesh2 {\n vertex_vectors { ").append(n).append(",\n");
        for (int i = 0; i < n; i++) {
            sb.append('<').append(BenchMeshes.number(p[3 * i])).append(',').append(BenchMeshes.number(p[3 * i + 1])).append(',')
                    .append(BenchMeshes.number(p[3 * i + 2])).append('>').append(i + 1 < n ? ",\n" : "\n");
            spill.check();
        }
        long triangles = 0;
        for (int f = 0; f < m.faceCount(); f++) triangles += Math.max(0, m.faceSizes()[f] - 2);
        sb.append(" }\n face_indices { ").append(triangles).append(",\n");
        int[] idx = m.vertexIndex();
        long written = 0;
        for (int f = 0, start = 0; f < m.faceCount(); start += m.faceSizes()[f], f++) {
            for (int k = 1; k + 1 < m.faceSizes()[f]; k++) {
                sb.append('<').append(idx[start]).append(',').append(idx[start + k]).append(',').append(idx[start + k + 1]).append('>')
                        .append(++written < triangles ? ",\n" : "\n");
                spill.check();
            }
        }
        sb.append(" }\n}\n");
        spill.flush();
    }

    /** Writes the text gathered so far once it is large, so a 2M-triangle mesh never sits in one string. */
    private record Spill(OutputStream out, StringBuilder sb) {
        void check() {
            if (sb.length() > 60000) {
                try {
                    flush();
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            }
        }

        void flush() throws IOException {
            out.write(sb.toString().getBytes(StandardCharsets.US_ASCII));
            sb.setLength(0);
        }
    }

    /** Writes {@link #writeMesh2} of {@code m} into {@code file}. */
    static void writeMesh2(Path file, MeshData m) throws IOException {
        try {
            AtomicFile.write(file, out -> writeMesh2(out, m));
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
    }
}
