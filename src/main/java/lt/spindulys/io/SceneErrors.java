package lt.spindulys.io;

import java.util.List;
import java.util.regex.Pattern;

import lt.spindulys.io.SceneBlockReader.Prop;
import lt.spindulys.io.SceneBlockReader.Props;
import lt.spindulys.io.SceneGrammar.Key;
import lt.spindulys.io.SceneLexer.Token;

/**
 * Where a scene file's errors are reported: a message, or a library check's
 * IllegalArgumentException, made into a {@link SceneException} at a token's file:line:column.
 * One per parse, shared by the block reader, the object factory and the asset cache.
 */
final class SceneErrors {
    private final String file;

    /** @param file the file as messages name it (null: "&lt;input&gt;") */
    SceneErrors(String file) {
        this.file = file;
    }

    SceneException error(Token at, String message) {
        return new SceneException(file, at.line(), at.column(), message);
    }

    SceneException wrap(Token at, IllegalArgumentException e) {
        return wrap(at, "", e);
    }

    SceneException wrap(Token at, String prefix, IllegalArgumentException e) {
        return new SceneException(file, at.line(), at.column(), prefix + e.getMessage(), e);
    }

    /**
     * Places a constructor's complaint at the key it names (the first key of the block, in
     * grammar order, that was given and that the message mentions as a word), else at the
     * statement: "sphere radius must be ..." is reported at 'radius'.
     */
    SceneException blame(Props p, IllegalArgumentException e) {
        String message = e.getMessage() == null ? "" : e.getMessage();
        for (Key k : p.block.keys()) {
            Prop pr = p.first.get(k.name());
            if (pr != null && Pattern.compile("(?<![A-Za-z0-9_])" + Pattern.quote(k.name()) + "(?![A-Za-z0-9_])").matcher(message).find()) {
                return wrap(pr.at(), e);
            }
        }
        return wrap(p.opener, e);
    }

    /** "a, b or c". */
    static String orList(List<String> words) { return list(words, "or"); }

    /** "a, b and c". */
    static String andList(List<String> words) { return list(words, "and"); }

    private static String list(List<String> words, String conjunction) {
        if (words.size() == 1) return words.get(0);
        return String.join(", ", words.subList(0, words.size() - 1)) + " " + conjunction + " " + words.get(words.size() - 1);
    }
}
