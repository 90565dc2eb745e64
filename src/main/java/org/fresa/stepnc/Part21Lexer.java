package org.fresa.stepnc;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Locale;

/**
 * The tokens of ISO 10303-21 (clause 6), read from a Reader through a fixed buffer so that a
 * large file is never held as one string. Comments are skipped wherever whitespace may stand.
 * Every token carries the line and column where it starts.
 *
 * <p>Lenient where real files are: keywords in lower case are upper-cased, tabs and form feeds
 * count as space, a backslash that starts no known escape is kept as a character.
 */
final class Part21Lexer {

    enum Tok {
        KEYWORD,
        INSTANCE,
        INTEGER,
        REAL,
        STRING,
        ENUMERATION,
        BINARY,
        DOLLAR,
        STAR,
        LPAREN,
        RPAREN,
        COMMA,
        EQUALS,
        SEMICOLON,
        EOF
    }

    private static final int EOF_CHAR = -1;

    private final Reader in;
    private final String source;
    // 8 Ki chars: the reader below decodes 8 KiB at a time anyway, and a larger buffer is cleared
    // on every read of a small file
    private final char[] buf = new char[1 << 13];
    private int pos;
    private int lim;
    private int line = 1;
    private int col = 1;
    private long charsRead;

    // the current token
    Tok tok;
    String text;
    long longValue;
    double doubleValue;
    int tokLine;
    int tokCol;
    /** Set by the parser so that messages name the instance being read. */
    long currentInstance;

    private final StringBuilder sb = new StringBuilder();
    // the characters of the current keyword, enumeration or number, without a StringBuilder's
    // per-character checks; a number's String is built only when a message or parseDouble needs it
    private char[] word = new char[64];
    private int wordLength;
    private final Keywords keywords = new Keywords();

    Part21Lexer(Reader in, String source) {
        this.in = in;
        this.source = source;
    }

    long charsRead() {
        return charsRead;
    }

    StepParseException error(int l, int c, String problem) {
        return new StepParseException(source, l, c, currentInstance, problem);
    }

    StepParseException errorHere(String problem) {
        return error(tokLine, tokCol, problem);
    }

    private int peekChar() throws IOException {
        return pos < lim || fill() ? buf[pos] : EOF_CHAR;
    }

    /** Refills the exhausted buffer; false at the end of the input. */
    private boolean fill() throws IOException {
        int n = in.read(buf, 0, buf.length);
        if (n <= 0) {
            return false;
        }
        // a UTF-8 byte order mark (Windows editors write one) is no character of the file
        pos = charsRead == 0 && buf[0] == '\uFEFF' ? 1 : 0;
        lim = n;
        charsRead += n;
        return pos < lim || fill();
    }

    /** Appends c to the current word. */
    private void addWord(char c) {
        if (wordLength == word.length) {
            word = Arrays.copyOf(word, wordLength * 2);
        }
        word[wordLength++] = c;
    }

    /** The next character if it is a decimal digit (consumed), else -1. */
    private int digit() throws IOException {
        if (pos < lim || fill()) {
            char c = buf[pos];
            if (c >= '0' && c <= '9') {
                pos++;
                col++;
                return c;
            }
        }
        return -1;
    }

    private int readChar() throws IOException {
        int c = peekChar();
        if (c == EOF_CHAR) {
            return c;
        }
        pos++;
        if (c == '\n') {
            line++;
            col = 1;
        } else {
            col++;
        }
        return c;
    }

    /** Advances to the next token. */
    void next() throws IOException, StepParseException {
        skipSpaceAndComments();
        tokLine = line;
        tokCol = col;
        int c = peekChar();
        if (c == EOF_CHAR) {
            tok = Tok.EOF;
            text = "end of file";
            return;
        }
        switch (c) {
            case '(' -> single(Tok.LPAREN);
            case ')' -> single(Tok.RPAREN);
            case ',' -> single(Tok.COMMA);
            case '=' -> single(Tok.EQUALS);
            case ';' -> single(Tok.SEMICOLON);
            case '$' -> single(Tok.DOLLAR);
            case '*' -> single(Tok.STAR);
            case '#' -> instanceName();
            case '\'' -> string();
            case '"' -> binary();
            case '.' -> enumeration();
            default -> {
                if (c == '+' || c == '-' || isDigit(c)) {
                    number();
                } else if (isLetter(c) || c == '_' || c == '!') {
                    keyword();
                } else {
                    throw error(line, col, "unexpected character " + describe(c));
                }
            }
        }
    }

    private static final String[] SINGLE = new String[128];

    static {
        for (char c : "(),=;$*".toCharArray()) {
            SINGLE[c] = String.valueOf(c);
        }
    }

    /** A one-character token; next() has just peeked it, so it is at pos and is no line break. */
    private void single(Tok t) {
        text = SINGLE[buf[pos++]];
        col++;
        tok = t;
    }

    private void skipSpaceAndComments() throws IOException, StepParseException {
        while (true) {
            // the run of white space in the buffer, counted as readChar counts it
            char[] b = buf;
            int p = pos;
            int end = lim;
            while (p < end) {
                char ch = b[p];
                if (ch == '\n') {
                    line++;
                    col = 1;
                } else if (ch == ' ' || ch == '\r' || ch == '\t' || ch == '\f') {
                    col++;
                } else {
                    break;
                }
                p++;
            }
            pos = p;
            int c = peekChar();
            if (c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\f') {
                continue;
            } else if (c == '/') {
                int l = line;
                int cc = col;
                readChar();
                if (peekChar() != '*') {
                    throw error(l, cc, "unexpected character '/' (a comment starts with /*)");
                }
                readChar();
                int prev = 0;
                while (true) {
                    int d = readChar();
                    if (d == EOF_CHAR) {
                        throw error(l, cc, "comment opened here is not closed with */ before the end of the file");
                    }
                    if (prev == '*' && d == '/') {
                        break;
                    }
                    prev = d;
                }
            } else {
                return;
            }
        }
    }

    private void instanceName() throws IOException, StepParseException {
        readChar();
        long v = 0;
        int digits = 0;
        boolean overflow = false;
        sb.setLength(0);
        for (int ch = digit(); ch >= 0; ch = digit()) {
            int d = ch - '0';
            digits++;
            if (overflow || v > (Long.MAX_VALUE - d) / 10) {
                overflow = true;
                if (sb.length() == 0) {
                    sb.append(v);
                }
                sb.append((char) ('0' + d));
            } else {
                v = v * 10 + d;
            }
        }
        if (digits == 0) {
            throw errorHere("'#' must be followed by the digits of an instance name");
        }
        if (overflow) {
            throw errorHere("instance name #" + abbreviate(sb.toString()) + " is larger than 64 bits (at most #"
                    + Long.MAX_VALUE + ")");
        }
        longValue = v;
        text = null;
        wordLength = 0;
        tok = Tok.INSTANCE;
    }

    private static final double[] POW10 = new double[23];

    static {
        double p = 1;
        for (int i = 0; i < POW10.length; i++) {
            POW10[i] = p;
            p *= 10;
        }
    }

    /** The text of the current token, also for numbers, whose text is built only when asked for. */
    String tokenText() {
        return text != null ? text : wordText();
    }

    private String wordText() {
        return new String(word, 0, wordLength);
    }

    /**
     * A number, read character by character through the buffer (a number may straddle one of its
     * refills), its digits kept as a long while they are few enough to be exact.
     */
    private void number() throws IOException, StepParseException {
        wordLength = 0;
        int c = peekChar();
        boolean negative = false;
        if (c == '+' || c == '-') {
            negative = c == '-';
            addWord((char) readChar());
        }
        if (!isDigit(peekChar())) {
            throw errorHere("a sign must be followed by digits");
        }
        // the digits as a long while they are few enough to be exact (Clinger's fast path)
        long mantissa = 0;
        int significant = 0;
        int scale = 0;
        for (int d = digit(); d >= 0; d = digit()) {
            addWord((char) d);
            if (significant < 18) {
                mantissa = mantissa * 10 + (d - '0');
                if (mantissa != 0) {
                    significant++;
                }
            } else {
                significant++;
                scale++;
            }
        }
        boolean real = false;
        if (peekChar() == '.') {
            real = true;
            addWord((char) readChar());
            for (int d = digit(); d >= 0; d = digit()) {
                addWord((char) d);
                if (significant < 18) {
                    mantissa = mantissa * 10 + (d - '0');
                    if (mantissa != 0) {
                        significant++;
                    }
                    scale--;
                } else {
                    significant++;
                }
            }
            int e = peekChar();
            if (e == 'E' || e == 'e') {
                addWord((char) readChar());
                int s = peekChar();
                boolean expNegative = false;
                if (s == '+' || s == '-') {
                    expNegative = s == '-';
                    addWord((char) readChar());
                }
                if (!isDigit(peekChar())) {
                    throw errorHere("the exponent of " + abbreviate(wordText()) + " has no digits");
                }
                int exp = 0;
                for (int d = digit(); d >= 0; d = digit()) {
                    addWord((char) d);
                    if (exp < 100_000) {
                        exp = exp * 10 + (d - '0');
                    }
                }
                scale += expNegative ? -exp : exp;
            }
        }
        numberValue(real, negative, mantissa, significant, scale);
    }

    /** The value of the number just read, whose characters are in word. */
    private void numberValue(boolean real, boolean negative, long mantissa, int significant, int scale)
            throws StepParseException {
        text = null;
        if (real) {
            // all digits kept (at most 18) and the mantissa at most 2^53, as the 16 digits of
            // 0.5235987755982988 are: then it and the power of ten are exact doubles, and one
            // rounding gives parseDouble's correctly rounded value
            if (significant <= 18 && mantissa <= 1L << 53 && scale >= -22 && scale <= 22) {
                double m = mantissa;
                doubleValue = scale >= 0 ? m * POW10[scale] : m / POW10[-scale];
                if (negative) {
                    doubleValue = -doubleValue;
                }
            } else {
                doubleValue = Double.parseDouble(wordText());
            }
            if (!Double.isFinite(doubleValue)) {
                throw errorHere("the number " + abbreviate(wordText()) + " is out of range");
            }
            tok = Tok.REAL;
        } else {
            if (significant < 18) {
                longValue = negative ? -mantissa : mantissa;
            } else {
                try {
                    longValue = Long.parseLong(wordText());
                } catch (NumberFormatException ex) {
                    throw errorHere("the integer " + abbreviate(wordText()) + " is larger than 64 bits");
                }
            }
            tok = Tok.INTEGER;
        }
    }

    private void keyword() throws IOException {
        wordLength = 0;
        char first = (char) readChar();
        addWord(first);
        // '-' only occurs in ISO-10303-21 and END-ISO-10303-21; the parser checks the spelling
        int h = wordRun(true, first);
        text = keywords.upperCase(word, wordLength, h);
        tok = Tok.KEYWORD;
    }

    private void enumeration() throws IOException, StepParseException {
        readChar();
        wordLength = 0;
        int h = wordRun(false, 0);
        if (wordLength == 0 || peekChar() != '.') {
            throw errorHere("an enumeration is written .NAME. (letters, digits, _ between two dots)");
        }
        readChar();
        // the same upper-casing as a keyword's, and a file repeats a few enumerations many times
        text = keywords.upperCase(word, wordLength, h);
        tok = Tok.ENUMERATION;
    }

    /**
     * Appends the letters, digits, '_' (and '-' when asked) that follow, straight from the buffer.
     * Returns the String hash of the word, continued from h, its value for the characters before.
     */
    private int wordRun(boolean dash, int h) throws IOException {
        do {
            char[] b = buf;
            int p = pos;
            int l = lim;
            while (p < l) {
                char c = b[p];
                if (!(isLetter(c) || isDigit(c) || c == '_' || (dash && c == '-'))) {
                    break;
                }
                addWord(c);
                h = 31 * h + c;
                p++;
            }
            col += p - pos;
            pos = p;
            if (p < l) {
                return h;
            }
        } while (fill());
        return h;
    }

    private void binary() throws IOException, StepParseException {
        readChar();
        sb.setLength(0);
        while (true) {
            int c = readChar();
            if (c == '"') {
                break;
            }
            if (c == EOF_CHAR) {
                throw errorHere("binary opened here is not closed with \" before the end of the file");
            }
            if (!(isDigit(c) || (c >= 'A' && c <= 'F') || (c >= 'a' && c <= 'f'))) {
                throw error(line, col - 1, "a binary holds hexadecimal digits only, found " + describe(c));
            }
            sb.append((char) c);
        }
        text = sb.toString();
        tok = Tok.BINARY;
    }

    private void string() throws IOException, StepParseException {
        readChar();
        if (peekChar() == '\'') {
            readChar();
            if (peekChar() != '\'') {
                text = "";
                tok = Tok.STRING;
                return;
            }
            // '' inside a string: an escaped quote at the start
            readChar();
            sb.setLength(0);
            sb.append('\'');
            stringRest();
            return;
        }
        sb.setLength(0);
        stringRest();
    }

    private void stringRest() throws IOException, StepParseException {
        Charset page = StandardCharsets.ISO_8859_1;
        while (true) {
            // the plain characters up to the next quote, backslash or line break, in one append
            char[] b = buf;
            int p = pos;
            int l = lim;
            while (p < l) {
                char ch = b[p];
                if (ch == '\'' || ch == '\\' || ch == '\n' || ch == '\r') {
                    break;
                }
                p++;
            }
            if (p > pos) {
                sb.append(b, pos, p - pos);
                col += p - pos;
                pos = p;
            }
            int c = readChar();
            if (c == EOF_CHAR) {
                throw errorHere("string opened here is not closed with ' before the end of the file");
            }
            if (c == '\'') {
                if (peekChar() == '\'') {
                    readChar();
                    sb.append('\'');
                    continue;
                }
                break;
            }
            if (c == '\n' || c == '\r') {
                // clause 6.4.3: line breaks inside a string are not part of its value
                continue;
            }
            if (c == '\\') {
                page = escape(page);
                continue;
            }
            sb.append((char) c);
        }
        text = sb.toString();
        tok = Tok.STRING;
    }

    /** After a backslash inside a string: decodes one escape, returns the code page in force. */
    private Charset escape(Charset page) throws IOException, StepParseException {
        int c = peekChar();
        int l = line;
        int cc = col - 1;
        if (c == '\\') {
            readChar();
            sb.append('\\');
            return page;
        }
        if (c == 'S') {
            readChar();
            expectChar('\\', l, cc, "\\S\\ escape");
            int ch = readChar();
            if (ch == EOF_CHAR || ch == '\'' && peekChar() != '\'') {
                throw error(l, cc, "\\S\\ must be followed by one character");
            }
            if (ch == '\'') {
                readChar();
            }
            byte b = (byte) ((ch & 0x7f) + 128);
            sb.append(new String(new byte[] {b}, page));
            return page;
        }
        if (c == 'P') {
            readChar();
            int p = readChar();
            if (p < 'A' || p > 'I') {
                throw error(l, cc, "\\P escape names a code page A to I (ISO 8859-1 to -9)");
            }
            expectChar('\\', l, cc, "\\P escape");
            try {
                return Charset.forName("ISO-8859-" + (p - 'A' + 1));
            } catch (RuntimeException e) {
                return StandardCharsets.ISO_8859_1;
            }
        }
        if (c == 'X') {
            readChar();
            int k = readChar();
            if (k == '\\') {
                sb.append((char) hex(2, l, cc));
                return page;
            }
            if (k == '2' || k == '4') {
                expectChar('\\', l, cc, "\\X" + (char) k + "\\ escape");
                int width = k == '2' ? 4 : 8;
                while (true) {
                    if (peekChar() == '\\') {
                        readChar();
                        if (readChar() != 'X' || readChar() != '0' || readChar() != '\\') {
                            throw error(l, cc, "\\X" + (char) k + "\\ escape must end with \\X0\\");
                        }
                        return page;
                    }
                    int code = hex(width, l, cc);
                    if (width == 4) {
                        sb.append((char) code);
                    } else if (Character.isValidCodePoint(code)) {
                        sb.appendCodePoint(code);
                    } else {
                        throw error(l, cc, "\\X4\\ escape holds an invalid code point");
                    }
                }
            }
            throw error(l, cc, "unknown escape \\X" + describe(k) + " (expected \\X\\, \\X2\\ or \\X4\\)");
        }
        // not an escape: a lone backslash, as some writers leave in paths
        sb.append('\\');
        return page;
    }

    private void expectChar(char want, int l, int c, String what) throws IOException, StepParseException {
        if (readChar() != want) {
            throw error(l, c, what + " is malformed");
        }
    }

    private int hex(int digits, int l, int c) throws IOException, StepParseException {
        int v = 0;
        for (int i = 0; i < digits; i++) {
            int d = Character.digit(readChar(), 16);
            if (d < 0) {
                throw error(l, c, "escape expects " + digits + " hexadecimal digits");
            }
            v = v * 16 + d;
        }
        return v;
    }

    private static boolean isDigit(int c) {
        return c >= '0' && c <= '9';
    }

    private static boolean isLetter(int c) {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
    }

    private static String describe(int c) {
        if (c == EOF_CHAR) {
            return "end of file";
        }
        if (c >= 0x20 && c < 0x7f) {
            return "'" + (char) c + "'";
        }
        return String.format(Locale.ROOT, "U+%04X", c);
    }

    private static String abbreviate(String s) {
        return s.length() > 30 ? s.substring(0, 27) + "..." : s;
    }

    /**
     * One String per distinct keyword spelling, found without building a String: a large file
     * repeats a few hundred entity names millions of times. Kept for its share of the reader's
     * margin (docs/performance.md, "Fast paths"): looking keywords up through Arrays.equals was 9 %
     * of a read of example 2, and building a String per keyword allocated more than the store.
     */
    private static final class Keywords {
        private char[][] spelled = new char[256][];
        private int[] hashes = new int[256];
        private String[] upper = new String[256];
        private int n;

        /** @param h the String hash of w[0, len) */
        String upperCase(char[] w, int len, int h) {
            int mask = spelled.length - 1;
            int slot = (h ^ (h >>> 16)) & mask;
            while (true) {
                char[] s = spelled[slot];
                if (s == null) {
                    break;
                }
                if (hashes[slot] == h && s.length == len && same(s, w, len)) {
                    return upper[slot];
                }
                slot = (slot + 1) & mask;
            }
            char[] s = Arrays.copyOf(w, len);
            String u = new String(s).toUpperCase(Locale.ROOT);
            spelled[slot] = s;
            hashes[slot] = h;
            upper[slot] = u;
            if (++n * 2 > spelled.length) {
                grow();
            }
            return u;
        }

        // a plain loop: the words are short, and Arrays.equals's range checks and mismatch call
        // cost more than the comparison here
        private static boolean same(char[] a, char[] b, int n) {
            for (int i = 0; i < n; i++) {
                if (a[i] != b[i]) {
                    return false;
                }
            }
            return true;
        }

        private void grow() {
            char[][] os = spelled;
            int[] oh = hashes;
            String[] ou = upper;
            spelled = new char[os.length * 2][];
            hashes = new int[os.length * 2];
            upper = new String[os.length * 2];
            int mask = spelled.length - 1;
            for (int i = 0; i < os.length; i++) {
                if (os[i] != null) {
                    int h = oh[i];
                    int slot = (h ^ (h >>> 16)) & mask;
                    while (spelled[slot] != null) {
                        slot = (slot + 1) & mask;
                    }
                    spelled[slot] = os[i];
                    hashes[slot] = h;
                    upper[slot] = ou[i];
                }
            }
        }
    }
}
