package lt.spindulys.plugin;

import java.util.List;

/**
 * Plugins whose id or name is unusable, listed only in jars a test makes
 * ({@link OutputPluginsFolderTest}): the loader must leave each out with one line and go on.
 */
public final class BrokenNamePlugins {
    private BrokenNamePlugins() {}

    /** Everything but the id and name a working plugin needs. */
    abstract static class Base implements OutputPlugin {
        @Override public String description() { return "Broken on purpose."; }
        @Override public List<String> fileExtensions() { return List.of("txt"); }
        @Override public List<PluginOption> options(List<DisplayedSurface> surfaces, PluginView view) { return List.of(); }
        @Override public PluginResult run(PluginRequest request) { throw new UnsupportedOperationException(); }
    }

    /** name() returns null. */
    public static final class NullName extends Base {
        /** For ServiceLoader. */
        public NullName() {}

        @Override public String id() { return "null-name"; }
        @Override public String name() { return null; }
    }

    /** name() throws. */
    public static final class ThrowingName extends Base {
        /** For ServiceLoader. */
        public ThrowingName() {}

        @Override public String id() { return "throwing-name"; }
        @Override public String name() { throw new IllegalStateException("no name\nat all"); }
    }

    /** name() is blank. */
    public static final class BlankName extends Base {
        /** For ServiceLoader. */
        public BlankName() {}

        @Override public String id() { return "blank-name"; }
        @Override public String name() { return " \t"; }
    }

    /** The ray tracer's id under another name. */
    public static final class DuplicateId extends Base {
        /** For ServiceLoader. */
        public DuplicateId() {}

        @Override public String id() { return "raytrace"; }
        @Override public String name() { return "Another tracer"; }
    }
}
