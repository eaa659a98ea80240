package lt.spindulys.scene;

import java.nio.file.Path;
import java.util.Collection;
import java.util.Objects;

import lt.spindulys.files.FileNames;

/**
 * A file a run reads: the scene file, a mesh, a material library, a texture or environment
 * image, an unwrap, a tile. The scene parser records each one on the {@link SceneBuilder} it
 * returns ({@link SceneBuilder#inputFiles()}), so that a run can refuse an output that would
 * replace one of its own inputs ({@link #checkOutput}) before it writes or renders anything.
 *
 * @param path the file as it was opened (the scene file as it was given, the files it names resolved against its folder)
 * @param what what it is, for messages: "scene file", "mesh file", "material library", "texture image", ...
 * @param at   where it was named, such as "scene.dat:3:12", or null when it was given directly
 */
public record InputFile(Path path, String what, String at) {
    /**
     * @throws NullPointerException if {@code path} or {@code what} is null
     */
    public InputFile {
        Objects.requireNonNull(path, "path");
        Objects.requireNonNull(what, "what");
    }

    /**
     * An output refused because it is one of the run's inputs; bad input, as the message says
     * which input and where it was named.
     */
    public static final class OutputIsInputException extends IllegalArgumentException {
        private static final long serialVersionUID = 1L;

        private final transient InputFile input;

        OutputIsInputException(Path output, InputFile input) {
            super("output '" + output + "' is an input of this run (the " + input.what() + (input.at() != null ? " named at " + input.at() : " '" + input.path() + "'")
                    + "); choose another name");
            this.input = input;
        }

        /**
         * The input the output would have replaced.
         *
         * @return the input
         */
        public InputFile input() { return input; }
    }

    /**
     * Refuses an output that is one of {@code inputs}: the same file, whatever links lead to it
     * ({@link FileNames#isSameFile}). Nothing is written or created.
     *
     * @param output a file the run is to write
     * @param inputs the files it reads
     * @throws OutputIsInputException naming the output, the input and where it was named:
     *         {@code output 'g.obj' is an input of this run (the mesh file named at scene.dat:3:12); choose another name}
     */
    public static void checkOutput(Path output, Collection<InputFile> inputs) {
        for (InputFile in : inputs) {
            if (FileNames.isSameFile(output, in.path())) throw new OutputIsInputException(output, in);
        }
    }
}
