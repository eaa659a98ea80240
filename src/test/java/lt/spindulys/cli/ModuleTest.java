package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.InputStream;
import java.lang.module.ModuleDescriptor;
import java.lang.reflect.Executable;
import java.lang.reflect.Field;
import java.lang.reflect.GenericArrayType;
import java.lang.reflect.Member;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.Type;
import java.lang.reflect.WildcardType;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The compiled classes run as the module {@code lt.spindulys} and from the class path, each with
 * and without {@code --add-modules jdk.incubator.vector}, in child JVMs started with this JVM's
 * java on the build's classes folder (the tests themselves run on the class path); and the module
 * descriptor exports exactly the library's API.
 */
class ModuleTest {
    /**
     * The packages a library user needs: scene building, objects, materials, textures, cameras,
     * lights, rendering, image output and mesh IO (with the mesh and control-mesh types it reads
     * and writes). The rest (per-ray machinery, acceleration structures, the CLI) stays inside.
     */
    private static final Set<String> API = Set.of("lt.spindulys.camera", "lt.spindulys.denoise", "lt.spindulys.image", "lt.spindulys.io",
            "lt.spindulys.material", "lt.spindulys.math", "lt.spindulys.mesh", "lt.spindulys.plugin", "lt.spindulys.render", "lt.spindulys.scene",
            "lt.spindulys.subdiv", "lt.spindulys.texture");

    /**
     * Six spheres, more than one leaf of the scene's structure, so that with the vector module the
     * object level is a wide BVH and its vector box test runs; no mesh, so no JIT warm-up.
     */
    private static final String SCENE = """
            settings { width 24 height 16 samples 1 }
            camera { eye 0 1 -6 lookat 0 0.5 0 fov 50 }
            light { position -4 6 -4 intensity 1 }
            plane { normal 0 1 0 offset 0 }
            sphere { center -2 0.5 0 radius 0.5 }
            sphere { center -1 0.5 1 radius 0.5 }
            sphere { center 0 0.5 0 radius 0.5 }
            sphere { center 1 0.5 1 radius 0.5 }
            sphere { center 2 0.5 0 radius 0.5 }
            sphere { center 0 1.5 2 radius 0.5 }
            """;

    /**
     * Internal types the exported API may name, by design: the per-ray methods of the scene's
     * objects take the renderer's records, and a mesh is the primitive set of its own structure.
     * The compiler's {@code [exports]} lint is off (see pom.xml); this list is what it would
     * report, and anything new fails here instead.
     */
    private static final Set<String> MACHINERY = Set.of("lt.spindulys.trace.Hit", "lt.spindulys.trace.TraceContext",
            "lt.spindulys.trace.ShadingData", "lt.spindulys.trace.SpanBuffer", "lt.spindulys.trace.TracedObject",
            "lt.spindulys.accel.PrimitiveSet", "lt.spindulys.accel.TriangleSet", "lt.spindulys.accel.PrimitiveHit",
            "lt.spindulys.accel.TraversalScratch");

    @TempDir Path dir;

    @Test
    void theExportedApiNamesNoInternalTypeButTheRenderersRecords() throws Exception {
        Path classes = classes();
        List<String> leaks = new ArrayList<>();
        try (Stream<Path> files = Files.walk(classes)) {
            for (Path f : (Iterable<Path>) files.filter(p -> p.toString().endsWith(".class"))::iterator) {
                String name = classes.relativize(f).toString().replace(java.io.File.separatorChar, '.').replaceAll("\\.class$", "");
                if (name.equals("module-info") || !API.contains(packageOf(name))) continue;
                Class<?> c = Class.forName(name, false, ModuleTest.class.getClassLoader());
                if (!visible(c)) continue;
                List<Type> named = new ArrayList<>();
                if (c.getGenericSuperclass() != null) named.add(c.getGenericSuperclass());
                named.addAll(List.of(c.getGenericInterfaces()));
                for (Type t : named) check(t, c.getName(), leaks);
                for (Method m : c.getDeclaredMethods()) {
                    if (visible(m) && !m.isSynthetic()) {
                        check(m.getGenericReturnType(), m.toString(), leaks);
                        checkAll(m, leaks);
                    }
                }
                for (var k : c.getDeclaredConstructors()) if (visible(k)) checkAll(k, leaks);
                for (Field x : c.getDeclaredFields()) if (visible(x)) check(x.getGenericType(), x.toString(), leaks);
            }
        }
        assertTrue(leaks.isEmpty(), "exported API naming types its users cannot reach:\n  " + String.join("\n  ", leaks));
    }

    private static String packageOf(String className) {
        return className.substring(0, className.lastIndexOf('.'));
    }

    /** Public, in a public (or protected nested) class all the way out. */
    private static boolean visible(Class<?> c) {
        if (c.isAnonymousClass() || c.isLocalClass() || c.isSynthetic()) return false;
        for (Class<?> k = c; k != null; k = k.getEnclosingClass()) {
            int m = k.getModifiers();
            if (!Modifier.isPublic(m) && !(k.getEnclosingClass() != null && Modifier.isProtected(m))) return false;
        }
        return true;
    }

    private static boolean visible(Member m) {
        return (Modifier.isPublic(m.getModifiers()) || Modifier.isProtected(m.getModifiers()));
    }

    private static void checkAll(Executable e, List<String> leaks) {
        for (Type t : e.getGenericParameterTypes()) check(t, e.toString(), leaks);
        for (Type t : e.getGenericExceptionTypes()) check(t, e.toString(), leaks);
    }

    private static void check(Type t, String where, List<String> leaks) {
        if (t instanceof Class<?> c) {
            while (c.isArray()) c = c.getComponentType();
            String n = c.getName();
            if (n.startsWith("lt.spindulys.") && !API.contains(c.getPackageName()) && !MACHINERY.contains(n)) leaks.add(where + " names " + n);
            // A JDK type from a module a user's module does not read through ours ("requires transitive").
            if (!n.startsWith("lt.spindulys.") && !c.isPrimitive() && !Set.of("java.base", "java.desktop").contains(c.getModule().getName())) {
                leaks.add(where + " names " + n + " of " + c.getModule().getName() + ", which module-info does not require transitively");
            }
        } else if (t instanceof ParameterizedType p) {
            check(p.getRawType(), where, leaks);
            for (Type a : p.getActualTypeArguments()) check(a, where, leaks);
        } else if (t instanceof GenericArrayType g) {
            check(g.getGenericComponentType(), where, leaks);
        } else if (t instanceof WildcardType w) {
            for (Type b : w.getUpperBounds()) check(b, where, leaks);
            for (Type b : w.getLowerBounds()) check(b, where, leaks);
        }
    }

    @Test
    void theDescriptorExportsExactlyTheApi() throws Exception {
        ModuleDescriptor d;
        try (InputStream in = Files.newInputStream(classes().resolve("module-info.class"))) {
            d = ModuleDescriptor.read(in);
        }
        assertEquals("lt.spindulys", d.name());
        Set<String> exported = new TreeSet<>();
        for (ModuleDescriptor.Exports e : d.exports()) {
            assertFalse(e.isQualified(), "a qualified export: " + e);
            exported.add(e.source());
        }
        assertEquals(new TreeSet<>(API), exported);
        assertTrue(d.opens().isEmpty(), "opens: " + d.opens());
        ModuleDescriptor.Requires vector = d.requires().stream().filter(r -> r.name().equals("jdk.incubator.vector")).findFirst().orElseThrow();
        assertEquals(Set.of(ModuleDescriptor.Requires.Modifier.STATIC), vector.modifiers(),
                "the vector module must be optional at run time (requires static)");
        assertTrue(d.requires().stream().anyMatch(r -> r.name().equals("java.desktop") && r.modifiers().contains(ModuleDescriptor.Requires.Modifier.TRANSITIVE)),
                "the API hands out java.desktop's BufferedImage: requires transitive java.desktop");
    }

    @Test
    void rendersAsAModuleAndFromTheClassPathWithAndWithoutTheVectorModule() throws Exception {
        Path scene = Files.writeString(dir.resolve("tiny.dat"), SCENE);
        String classes = classes().toString();
        List<String> asModule = List.of("--module-path", classes, "-m", "lt.spindulys/" + Main.class.getName());
        List<String> fromClassPath = List.of("-cp", classes, Main.class.getName());
        List<String> vector = List.of("--add-modules", "jdk.incubator.vector");

        String modulePlain = render(List.of(), asModule, scene, "module.png");
        String moduleVector = render(vector, asModule, scene, "module-vector.png");
        String pathPlain = render(List.of(), fromClassPath, scene, "path.png");
        String pathVector = render(vector, fromClassPath, scene, "path-vector.png");

        // Without the module both fall back to the scalar tree; with it both take the same path,
        // so the module reads the vector module exactly when the class path sees it.
        assertTrue(modulePlain.startsWith("(bvh: ") && modulePlain.contains("no jdk.incubator.vector module"), modulePlain);
        assertEquals(pathPlain, modulePlain);
        assertEquals(pathVector, moduleVector);
        byte[] reference = Files.readAllBytes(dir.resolve("path-vector.png"));
        assertArrayEquals(reference, Files.readAllBytes(dir.resolve("module-vector.png")), "the same image from the module");
        assertArrayEquals(Files.readAllBytes(dir.resolve("path.png")), Files.readAllBytes(dir.resolve("module.png")));

        for (List<String> vm : List.of(List.<String>of(), vector)) {
            for (List<String> launch : List.of(asModule, fromClassPath)) {
                Result r = java(vm, launch, List.of("--version"));
                assertEquals(0, r.status, r.output);
                assertTrue(r.output.startsWith("spindulys "), r.output);
            }
        }
        // The module carries the project's version in its descriptor, so --version names it there too.
        assertFalse(java(List.of(), asModule, List.of("--version")).output.contains("development build"));
    }

    /** Renders {@code scene} to {@code name} in the temporary folder; returns the structure line of --stats. */
    private String render(List<String> vm, List<String> launch, Path scene, String name) throws Exception {
        Path out = dir.resolve(name);
        Result r = java(vm, launch, List.of(scene.toString(), "-o", out.toString(), "--stats", "--quiet", "--threads", "1"));
        assertEquals(0, r.status, String.join(" ", vm) + " " + String.join(" ", launch) + ":\n" + r.output);
        assertTrue(Files.size(out) > 0, "no image written");
        byte[] head = Files.readAllBytes(out);
        assertEquals((byte) 0x89, head[0], "not a PNG");
        assertEquals("PNG", new String(head, 1, 3, StandardCharsets.US_ASCII), "not a PNG");
        // "build:   0.068 s (bvh: ...)": the structure without the time
        return r.output.lines().filter(l -> l.startsWith("build:")).map(l -> l.substring(l.indexOf('('))).collect(Collectors.joining("\n"));
    }

    private record Result(int status, String output) {}

    /** Runs this JVM's java with {@code vm} options, {@code launch} (how the main class is found) and {@code args}. */
    private Result java(List<String> vm, List<String> launch, List<String> args) throws Exception {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.add("-Xmx256m");
        cmd.addAll(vm);
        cmd.addAll(launch);
        cmd.addAll(args);
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true);
        pb.environment().remove("JAVA_TOOL_OPTIONS");
        pb.environment().remove("JDK_JAVA_OPTIONS");
        Process p = pb.start();
        p.getOutputStream().close();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (!p.waitFor(120, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            fail("the child JVM did not finish: " + cmd);
        }
        // The incubator's fixed start-up notice is not the program's output.
        output = output.replace("WARNING: Using incubator modules: jdk.incubator.vector\n", "");
        return new Result(p.exitValue(), output);
    }

    /** The folder of the compiled main classes (target/classes, or its -DbuildDir equivalent). */
    private static Path classes() throws Exception {
        Path classes = Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        assumeTrue(Files.isDirectory(classes), "the classes under test are not in a folder: " + classes);
        assertTrue(Files.isRegularFile(classes.resolve("module-info.class")), "no module-info.class in " + classes);
        return classes;
    }
}
