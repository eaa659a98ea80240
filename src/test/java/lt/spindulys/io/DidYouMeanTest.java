package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;

import org.junit.jupiter.api.Test;

/** Suggestions are made only for words of plausible length, so their cost is bounded whatever the input. */
class DidYouMeanTest {
    @Test
    void nearMissesAreSuggested() {
        assertEquals("radius", SceneGrammar.nearest("radus", List.of("center", "radius")));
        assertEquals(" (did you mean 'sphere'?)", SceneGrammar.didYouMean("shpere", SceneGrammar.statementNames()));
    }

    @Test
    void longWordsGetNoSuggestion() {
        // Up to 64 characters a long (user-defined) name is still matched ...
        assertEquals("a".repeat(64), SceneGrammar.nearest("a".repeat(63) + "b", List.of("a".repeat(64))));
        // ... beyond, not, even one edit away.
        assertNull(SceneGrammar.nearest("a".repeat(65) + "b", List.of("a".repeat(66))));
        // Nor a word longer than twice the longest candidate + 2.
        assertNull(SceneGrammar.nearest("abcdefgh", List.of("abc")));
        // A 10 MB word costs one pass over the candidates' lengths.
        assertEquals("", SceneGrammar.didYouMean("r".repeat(10 << 20), SceneGrammar.statementNames()));
    }
}
