package org.fresa.check;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The block reader's tape-mark rule against the pattern it stands for. */
class WordsTest {

    /**
     * A block is a tape mark or header (no words, no problem) exactly when the pattern
     * {@code ^[Nn]\s*\d+\s*} stripped from it leaves a text starting with {@code %}: 50 000
     * random blocks of block numbers, blanks, digits, marks and words.
     */
    @Test
    void aTapeMarkIsWhatThePatternSaysItIs() {
        Random r = new Random(22);
        String alphabet = "NnNn  \t\u000B\f05%%G1X.-";
        for (int t = 0; t < 50_000; t++) {
            StringBuilder sb = new StringBuilder();
            for (int k = 1 + r.nextInt(8); k > 0; k--) {
                sb.append(alphabet.charAt(r.nextInt(alphabet.length())));
            }
            String s = sb.toString().trim();
            if (s.isEmpty()) {
                continue;
            }
            boolean expected = s.replaceFirst("^[Nn]\\s*\\d+\\s*", "").startsWith("%");
            Words.Block b = Words.block(1, s);
            boolean mark = b.words().isEmpty() && b.problem().isEmpty();
            assertEquals(expected, mark, () -> "'" + s + "'");
        }
    }
}
