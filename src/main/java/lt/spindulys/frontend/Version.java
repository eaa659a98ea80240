package lt.spindulys.frontend;

/** The program's version, as {@code render --version} and the bench's header print it. */
public final class Version {
    private Version() {}

    /** The project's version, or "development build" when the classes carry none (run from an IDE or target/classes). */
    public static String text() {
        String v = Version.class.getPackage().getImplementationVersion();
        // A jar's manifest gives the version on the class path; on the module path the
        // descriptor carries it (the compiler records the project's version there).
        if (v == null && Version.class.getModule().getDescriptor() != null) {
            v = Version.class.getModule().getDescriptor().rawVersion().orElse(null);
        }
        return v != null ? v : "development build";
    }
}
