package lt.spindulys.image;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;

import org.junit.jupiter.api.Test;

class AovTest {
    @Test
    void keywordsAndSuffixes() {
        assertEquals(List.of("depth", "normal", "object", "albedo", "noise"), Aov.keywords());
        for (Aov a : Aov.values()) assertSame(a, Aov.fromKeyword(a.keyword()));
        assertEquals(".depth.pfm", Aov.DEPTH.suffix());
        assertEquals(".normal.pfm", Aov.NORMAL.suffix());
        assertEquals(".object.png", Aov.OBJECT.suffix());
        assertEquals(".noise.pfm", Aov.NOISE.suffix());
        assertEquals(".albedo.pfm", Aov.ALBEDO.suffix());
    }

    @Test
    void filesBesideAnyMainFormatReplaceTheExtension() {
        for (String ext : List.of("png", "tga", "jpg", "jpeg", "pfm", "PNG")) {
            Path main = Path.of("renders", "out." + ext);
            assertEquals(Path.of("renders", "out.depth.pfm"), Aov.DEPTH.fileBeside(main), ext);
            assertEquals(Path.of("renders", "out.normal.pfm"), Aov.NORMAL.fileBeside(main), ext);
            assertEquals(Path.of("renders", "out.object.png"), Aov.OBJECT.fileBeside(main), ext);
        }
        // Only the last extension goes; a name without a folder stays without one.
        assertEquals(Path.of("a.b.object.png"), Aov.OBJECT.fileBeside(Path.of("a.b.png")));
    }

    @Test
    void parsesCommaSeparatedListsInPassOrder() {
        assertEquals(EnumSet.allOf(Aov.class), Aov.parseList("object,noise,albedo,depth,normal"));
        assertEquals(EnumSet.of(Aov.NORMAL), Aov.parseList("normal"));
        assertEquals(EnumSet.of(Aov.DEPTH, Aov.OBJECT), Aov.parseList("depth, object"));
        assertEquals(List.of(Aov.DEPTH, Aov.OBJECT), List.copyOf(Aov.parseList("object,depth")));
    }

    @Test
    void refusesUnknownRepeatedAndEmptyNames() {
        assertEquals("unknown AOV 'shadow' (expected depth, normal, object, albedo or noise)",
                assertThrows(IllegalArgumentException.class, () -> Aov.parseList("depth,shadow")).getMessage());
        assertEquals("AOV 'depth' listed twice",
                assertThrows(IllegalArgumentException.class, () -> Aov.parseList("depth,normal,depth")).getMessage());
        assertEquals("empty AOV name in 'depth,' (expected depth, normal, object, albedo or noise)",
                assertThrows(IllegalArgumentException.class, () -> Aov.parseList("depth,")).getMessage());
        assertThrows(IllegalArgumentException.class, () -> Aov.parseList(""));
        assertThrows(IllegalArgumentException.class, () -> Aov.fromKeyword("Depth"));
    }
}
