package org.fresa.check;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * Reads the blocks of an NC program into address words: comments ({@code (...)}, {@code ;} to
 * the end of the line) and tape marks or headers ({@code %}, {@code %_N_..._MPF}) carry none;
 * an address is a letter followed by a number, blanks allowed between them (the 7M's
 * {@code X 23680}), or a name with {@code =} ({@code TURN=2}).
 */
public final class Words {

    /** Most characters of a number a control reads; longer ones are refused, whatever their value. */
    static final int MAX_NUMBER_CHARS = 16;

    private Words() {}

    /**
     * One address word.
     *
     * @param address the letter (upper case) or name ({@code TURN})
     * @param value its number
     * @param text the number as written
     */
    public record Word(String address, double value, String text) {
        @Override
        public String toString() {
            return address + (address.length() > 1 ? "=" : "") + text;
        }
    }

    /**
     * One line of the program.
     *
     * @param line its line number in the text, from 1
     * @param text the line as written
     * @param words its address words in order
     * @param problem what could not be read, or empty
     */
    public record Block(int line, String text, List<Word> words, Optional<String> problem) {
        public Block {
            words = List.copyOf(words);
        }

        /** The first word of the address, if any. */
        public Optional<Word> word(String address) {
            // loops, not streams: the check asks every block of a 3 million-block program a dozen times
            for (Word w : words) {
                if (w.address().equals(address)) {
                    return Optional.of(w);
                }
            }
            return Optional.empty();
        }

        /** True when a word of the address has the value. */
        public boolean has(String address, double value) {
            for (Word w : words) {
                if (w.address().equals(address) && w.value() == value) {
                    return true;
                }
            }
            return false;
        }

        /** The block's N number as written, or "line L". */
        public String label() {
            return word("N")
                    .map(w -> "block N" + w.text() + " (line " + line + ")")
                    .orElse("line " + line);
        }
    }

    /** Every line of the program. */
    public static List<Block> blocks(String program) {
        List<Block> out = new ArrayList<>();
        String[] lines = program.split("\r?\n|\r", -1);
        for (int i = 0; i < lines.length; i++) {
            out.add(block(i + 1, lines[i]));
        }
        return out;
    }

    /** The words of a group such as {@code M64 P0} (the on and off words of a jet). */
    public static List<Word> group(String words) {
        Block b = block(0, words);
        if (b.problem().isPresent() || b.words().isEmpty()) {
            throw new IllegalArgumentException("not a group of words: " + words);
        }
        return b.words();
    }

    static Block block(int line, String text) {
        String s = stripComments(text).trim();
        List<Word> words = new ArrayList<>();
        int i = 0;
        int n = s.length();
        // a tape mark or a Siemens header, possibly after a block number (the 7M's "N05 %")
        if (tapeMark(s)) {
            return new Block(line, text, List.of(), Optional.empty());
        }
        while (i < n) {
            char c = s.charAt(i);
            if (c == ' ' || c == '\t') {
                i++;
                continue;
            }
            if (!Character.isLetter(c) || c > 127) {
                return new Block(line, text, words, Optional.of("'" + c + "' where an address letter was expected"));
            }
            int a = i;
            while (i < n && Character.isLetter(s.charAt(i)) && s.charAt(i) < 128) {
                i++;
            }
            String address = i == a + 1
                    ? LETTERS[Character.toUpperCase(s.charAt(a)) - 'A']
                    : s.substring(a, i).toUpperCase(Locale.ROOT);
            if (address.length() > 1) {
                if (i < n && s.charAt(i) == '=') {
                    i++;
                } else {
                    return new Block(line, text, words, Optional.of("'" + address + "' is not a word of the dialect"));
                }
            } else {
                while (i < n && (s.charAt(i) == ' ' || s.charAt(i) == '\t')) {
                    i++;
                }
            }
            int b = i;
            if (i < n && (s.charAt(i) == '+' || s.charAt(i) == '-')) {
                i++;
            }
            int digits = 0;
            while (i < n && Character.isDigit(s.charAt(i))) {
                i++;
                digits++;
            }
            if (i < n && s.charAt(i) == '.') {
                i++;
                while (i < n && Character.isDigit(s.charAt(i))) {
                    i++;
                    digits++;
                }
            }
            String num = s.substring(b, i);
            if (digits == 0) {
                return new Block(line, text, words, Optional.of("address " + address + " without a number"));
            }
            if (num.length() > MAX_NUMBER_CHARS) {
                return new Block(
                        line,
                        text,
                        words,
                        Optional.of("word " + address + num + " has " + num.length()
                                + " characters: no control reads a number that long (at most " + MAX_NUMBER_CHARS
                                + ")"));
            }
            words.add(new Word(address, Double.parseDouble(num), num));
        }
        return new Block(line, text, words, Optional.empty());
    }

    /** The one-letter addresses, upper case: one string each instead of one per word read. */
    private static final String[] LETTERS = new String[26];

    static {
        for (char c = 'A'; c <= 'Z'; c++) {
            LETTERS[c - 'A'] = String.valueOf(c);
        }
    }

    /**
     * True when the block, after a block number if any ({@code N}, blanks, digits, blanks), starts
     * with {@code %}: what the pattern {@code ^[Nn]\s*\d+\s*} stripped before it, without compiling
     * the pattern for every block.
     */
    private static boolean tapeMark(String s) {
        int n = s.length();
        int j = 0;
        if (n > 0 && (s.charAt(0) == 'N' || s.charAt(0) == 'n')) {
            int k = 1;
            while (k < n && blank(s.charAt(k))) {
                k++;
            }
            int d = k;
            while (k < n && s.charAt(k) >= '0' && s.charAt(k) <= '9') {
                k++;
            }
            if (k > d) {
                while (k < n && blank(s.charAt(k))) {
                    k++;
                }
                j = k;
            }
        }
        return j < n && s.charAt(j) == '%';
    }

    /** The regular expression's {@code \s}: space, tab, line feed, vertical tab, form feed, carriage return. */
    private static boolean blank(char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == 0x0B || c == '\f' || c == '\r';
    }

    private static String stripComments(String text) {
        StringBuilder sb = new StringBuilder(text.length());
        boolean inParen = false;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (inParen) {
                if (c == ')') {
                    inParen = false;
                }
            } else if (c == '(') {
                inParen = true;
            } else if (c == ';') {
                break;
            } else {
                sb.append(c);
            }
        }
        return sb.toString();
    }
}
