package lt.spindulys.viewer;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import lt.spindulys.files.FileNames;
import lt.spindulys.io.ObjReader;
import lt.spindulys.io.SceneException;
import lt.spindulys.io.WorkframeReader;
import lt.spindulys.limits.InputFiles;
import lt.spindulys.limits.MessageText;
import lt.spindulys.subdiv.SubdivInput;

/**
 * Reads what the viewer opens: OBJ meshes with OpenSubdiv tags ({@link ObjReader#readSubdiv}),
 * Workframe {@code .dat} meshes ({@link WorkframeReader#readMesh}) with the {@code .tex} unwrap of
 * the same base name beside them when there is one, and {@code .tex} unwraps on their own, for
 * a surface already open. Errors are the exceptions the readers throw, which
 * {@link lt.spindulys.frontend.FailureMessage#of} turns into the line the command line prints.
 */
public final class MeshLoader {
    private MeshLoader() {}

    /**
     * A mesh read from a file.
     *
     * @param name the file's name, shown in the surface list
     * @param source the file
     * @param input the control mesh with its tags (and UVs from the unwrap, if any)
     * @param unwrap the unwrap read with it, or null
     */
    public record Loaded(String name, Path source, SubdivInput input, Path unwrap) {}

    /**
     * True if {@code file} is a {@code .tex} unwrap (by its extension).
     *
     * @param file the file
     * @return whether it is an unwrap
     */
    public static boolean isUnwrap(Path file) {
        return FileNames.extension(file).equals("tex");
    }

    /**
     * Reads a mesh: {@code .obj} or {@code .dat} (with {@code NAME.tex} beside a {@code NAME.dat}).
     * The control mesh is built once here, so that a mesh whose topology cannot be refined is
     * refused when it is opened, not when it is first drawn.
     *
     * @param file the file
     * @return the mesh
     * @throws IOException if it cannot be read
     * @throws SceneException naming file:line:column of what is wrong in it, or the file when its kind is unknown
     * @throws IllegalArgumentException naming the mesh and the face or vertex that cannot be refined
     */
    public static Loaded load(Path file) throws IOException {
        String ext = FileNames.extension(file);
        SubdivInput in;
        Path unwrap = null;
        switch (ext) {
            case "obj" -> in = ObjReader.readSubdiv(file);
            case "dat" -> {
                in = SubdivInput.of(WorkframeReader.readMesh(file));
                Path tex = sibling(file, "tex");
                if (tex != null) {
                    in = withUnwrap(in, tex);
                    unwrap = tex;
                }
            }
            default -> {
                // A folder dropped on the window is named as a folder, not as a file of the wrong kind.
                String problem = InputFiles.problem(file);
                throw new SceneException(file.toString(), 0, 0, "the viewer opens .obj and .dat meshes and .tex unwraps, found "
                        + (problem != null ? (problem.startsWith("is ") ? "a path that " + problem : "nothing there (" + problem + ")") : ext.isEmpty() ? "a file without an extension" : "a ." + MessageText.cut(ext) + " file"));
            }
        }
        in.toControlMesh();
        return new Loaded(file.getFileName() == null ? file.toString() : file.getFileName().toString(), file, in, unwrap);
    }

    /**
     * The mesh with the texture coordinates of a {@code .tex} unwrap (either form).
     *
     * @param in the mesh
     * @param tex the unwrap
     * @return the mesh with UVs
     * @throws IOException if the unwrap cannot be read
     * @throws SceneException naming tex:line:column when it does not fit the mesh
     */
    public static SubdivInput withUnwrap(SubdivInput in, Path tex) throws IOException {
        return WorkframeReader.readTex(tex, in.mesh()).applyTo(in);
    }

    /** NAME.ext beside NAME.dat, in either case of the extension, if it is a regular file. */
    private static Path sibling(Path file, String ext) {
        String name = file.getFileName().toString();
        String base = name.substring(0, name.length() - 4);
        for (String e : new String[] {ext, ext.toUpperCase(Locale.ROOT)}) {
            Path p = file.resolveSibling(base + "." + e);
            if (Files.isRegularFile(p)) return p;
        }
        return null;
    }
}
