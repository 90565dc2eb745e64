package org.fresa.stepnc;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
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
        KEYWORD, INSTANCE, INTEGER, REAL, STRING, ENUMERATION, BINARY, DOLLAR, STAR,
        LPAREN, RPAREN, COMMA, EQUALS, SEMICOLON, EOF
    }

    private static final int EOF_CHAR = -1;

    private final Reader in;
    private final String source;
    private final char[] buf = new char[1 << 16];
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
        if (pos == lim) {
            int n = in.read(buf, 0, buf.length);
            if (n <= 0) {
                return EOF_CHAR;
            }
            pos = 0;
            lim = n;
            charsRead += n;
        }
        return buf[pos];
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

    private void single(Tok t) throws IOException {
        text = SINGLE[readChar()];
        tok = t;
    }

    private void skipSpaceAndComments() throws IOException, StepParseException {
        while (true) {
            int c = peekChar();
            if (c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\f') {
                readChar();
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
        while (isDigit(peekChar())) {
            int d = readChar() - '0';
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
        return text != null ? text : sb.toString();
    }

    private void number() throws IOException, StepParseException {
        sb.setLength(0);
        int c = peekChar();
        boolean negative = false;
        if (c == '+' || c == '-') {
            negative = c == '-';
            sb.append((char) readChar());
        }
        if (!isDigit(peekChar())) {
            throw errorHere("a sign must be followed by digits");
        }
        // the digits as a long while they are few enough to be exact (Clinger's fast path)
        long mantissa = 0;
        int significant = 0;
        int scale = 0;
        while (isDigit(peekChar())) {
            int d = readChar();
            sb.append((char) d);
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
            sb.append((char) readChar());
            while (isDigit(peekChar())) {
                int d = readChar();
                sb.append((char) d);
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
                sb.append((char) readChar());
                int s = peekChar();
                boolean expNegative = false;
                if (s == '+' || s == '-') {
                    expNegative = s == '-';
                    sb.append((char) readChar());
                }
                if (!isDigit(peekChar())) {
                    throw errorHere("the exponent of " + abbreviate(sb.toString()) + " has no digits");
                }
                int exp = 0;
                while (isDigit(peekChar())) {
                    int d = readChar();
                    sb.append((char) d);
                    if (exp < 100_000) {
                        exp = exp * 10 + (d - '0');
                    }
                }
                scale += expNegative ? -exp : exp;
            }
        }
        text = null;
        if (real) {
            if (significant <= 15 && scale >= -22 && scale <= 22) {
                // the mantissa and the power of ten are exact doubles: one rounding, as parseDouble
                double m = mantissa;
                doubleValue = scale >= 0 ? m * POW10[scale] : m / POW10[-scale];
                if (negative) {
                    doubleValue = -doubleValue;
                }
            } else {
                doubleValue = Double.parseDouble(sb.toString());
            }
            if (!Double.isFinite(doubleValue)) {
                throw errorHere("the number " + abbreviate(sb.toString()) + " is out of range");
            }
            tok = Tok.REAL;
        } else {
            if (significant < 18) {
                longValue = negative ? -mantissa : mantissa;
            } else {
                try {
                    longValue = Long.parseLong(sb.toString());
                } catch (NumberFormatException ex) {
                    throw errorHere("the integer " + abbreviate(sb.toString()) + " is larger than 64 bits");
                }
            }
            tok = Tok.INTEGER;
        }
    }

    private void keyword() throws IOException {
        sb.setLength(0);
        sb.append((char) readChar());
        while (true) {
            int c = peekChar();
            // '-' only occurs in ISO-10303-21 and END-ISO-10303-21; the parser checks the spelling
            if (isLetter(c) || isDigit(c) || c == '_' || c == '-') {
                sb.append((char) readChar());
            } else {
                break;
            }
        }
        text = keywords.upperCase(sb);
        tok = Tok.KEYWORD;
    }

    private void enumeration() throws IOException, StepParseException {
        readChar();
        sb.setLength(0);
        while (true) {
            int c = peekChar();
            if (isLetter(c) || isDigit(c) || c == '_') {
                sb.append((char) readChar());
            } else {
                break;
            }
        }
        if (sb.length() == 0 || peekChar() != '.') {
            throw errorHere("an enumeration is written .NAME. (letters, digits, _ between two dots)");
        }
        readChar();
        text = sb.toString().toUpperCase(Locale.ROOT);
        tok = Tok.ENUMERATION;
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
     * repeats a few hundred entity names millions of times.
     */
    private static final class Keywords {
        private String[] spelled = new String[256];
        private String[] upper = new String[256];
        private int n;

        String upperCase(StringBuilder sb) {
            int h = 0;
            int len = sb.length();
            for (int i = 0; i < len; i++) {
                h = 31 * h + sb.charAt(i);
            }
            int mask = spelled.length - 1;
            int slot = (h ^ (h >>> 16)) & mask;
            while (true) {
                String s = spelled[slot];
                if (s == null) {
                    break;
                }
                if (s.contentEquals(sb)) {
                    return upper[slot];
                }
                slot = (slot + 1) & mask;
            }
            String s = sb.toString();
            String u = s.toUpperCase(Locale.ROOT);
            spelled[slot] = s;
            upper[slot] = u;
            if (++n * 2 > spelled.length) {
                grow();
            }
            return u;
        }

        private void grow() {
            String[] os = spelled;
            String[] ou = upper;
            spelled = new String[os.length * 2];
            upper = new String[os.length * 2];
            int mask = spelled.length - 1;
            for (int i = 0; i < os.length; i++) {
                if (os[i] != null) {
                    int h = os[i].hashCode();
                    int slot = (h ^ (h >>> 16)) & mask;
                    while (spelled[slot] != null) {
                        slot = (slot + 1) & mask;
                    }
                    spelled[slot] = os[i];
                    upper[slot] = ou[i];
                }
            }
        }
    }
}
