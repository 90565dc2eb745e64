package org.fresa.dxf;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * The group-code/value pairs of a DXF file, ASCII or binary, with the line (ASCII) or byte
 * offset (binary) of each code for messages. Values are kept as text; binary doubles are written
 * with {@link Double#toString} so they read back exactly.
 */
final class DxfTags {

    static final byte[] BINARY_SENTINEL = "AutoCAD Binary DXF\r\n\u001a\0".getBytes(StandardCharsets.ISO_8859_1);

    final String source;
    final boolean binary;
    int size;
    /** Group codes from 0 to 32767 (all DXF uses); others are kept in {@link #wideCodes}. */
    private short[] codes = new short[1024];

    private java.util.Map<Integer, Integer> wideCodes;
    /** The values' bytes one after another (UTF-8, or the ANSI code page of older drawings). */
    private byte[] bytes = new byte[16 * 1024];

    private int used;
    /** Where value i starts in {@link #bytes}; value i ends where value i + 1 starts. */
    private int[] starts = new int[1025];
    /** Binary drawings: the byte offset of each group code; ASCII ones: code i is on line 2i + 1. */
    private int[] offsets;

    private DxfTags(String source, boolean binary) {
        this.source = source;
        this.binary = binary;
        this.offsets = binary ? new int[1024] : null;
    }

    int code(int index) {
        short c = codes[index];
        return c >= 0 ? c : wideCodes.get(index);
    }

    /** The value of tag index as text. */
    String value(int index) {
        int a = starts[index];
        int b = starts[index + 1];
        boolean ascii = true;
        for (int k = a; k < b && ascii; k++) {
            ascii = bytes[k] >= 0;
        }
        if (ascii) {
            return new String(bytes, a, b - a, StandardCharsets.ISO_8859_1);
        }
        try {
            return StandardCharsets.UTF_8
                    .newDecoder()
                    .onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT)
                    .decode(ByteBuffer.wrap(bytes, a, b - a))
                    .toString();
        } catch (CharacterCodingException e) {
            // pre-2007 drawings are in the ANSI code page; names only, geometry is unaffected
            return new String(bytes, a, b - a, StandardCharsets.ISO_8859_1);
        }
    }

    /** True when the value of tag index is exactly the given ASCII text (no string is made). */
    boolean valueIs(int index, String ascii) {
        int a = starts[index];
        int n = starts[index + 1] - a;
        if (n != ascii.length()) {
            return false;
        }
        for (int k = 0; k < n; k++) {
            if (bytes[a + k] != ascii.charAt(k)) {
                return false;
            }
        }
        return true;
    }

    /** The line of tag index's group code (ASCII), or its byte offset (binary). */
    int line(int index) {
        return binary ? offsets[index] : 2 * index + 1;
    }

    String where(int index) {
        int l = index < size ? line(index) : (size > 0 ? line(size - 1) : 0);
        return binary ? "byte " + l : "line " + l;
    }

    /** Where the value of tag index is: its line in ASCII (the line after the code). */
    String whereValue(int index) {
        return binary ? where(index) : "line " + (line(index) + 1);
    }

    private void grow() {
        int n = size * 3 / 2 + 16;
        codes = java.util.Arrays.copyOf(codes, n);
        starts = java.util.Arrays.copyOf(starts, n + 1);
        if (binary) {
            offsets = java.util.Arrays.copyOf(offsets, n);
        }
    }

    private void setCode(int code) {
        if (code >= 0 && code <= Short.MAX_VALUE) {
            codes[size] = (short) code;
        } else {
            codes[size] = -1;
            if (wideCodes == null) {
                wideCodes = new java.util.HashMap<>();
            }
            wideCodes.put(size, code);
        }
    }

    private void add(int code, byte[] value, int from, int len, int offset) {
        if (size + 1 >= codes.length) {
            grow();
        }
        if (used + len > bytes.length) {
            long n = Math.max((long) used + len, (long) bytes.length * 3 / 2);
            if (n > Integer.MAX_VALUE - 16) {
                throw new IllegalStateException("a drawing with more than 2 GB of values");
            }
            bytes = java.util.Arrays.copyOf(bytes, (int) n);
        }
        System.arraycopy(value, from, bytes, used, len);
        setCode(code);
        starts[size] = used;
        used += len;
        starts[size + 1] = used;
        if (binary) {
            offsets[size] = offset;
        }
        size++;
    }

    private void add(int code, String value, int offset) {
        byte[] b = value.getBytes(StandardCharsets.UTF_8);
        add(code, b, 0, b.length, offset);
    }

    /** A drawing ends with (0, EOF): without it the file was cut short and its end is missing. */
    private void requireEof(int lastLine) throws DxfException {
        if (size > 0 && code(size - 1) == 0 && valueIs(size - 1, "EOF")) {
            return;
        }
        throw new DxfException(
                source,
                binary ? 0 : lastLine,
                (binary ? "byte " + lastLine + ": " : "")
                        + "the drawing ends without its closing group 0 EOF (the file is truncated)");
    }

    static DxfTags parse(byte[] data, String source) throws DxfException {
        if (data.length >= BINARY_SENTINEL.length
                && Arrays.equals(Arrays.copyOf(data, BINARY_SENTINEL.length), BINARY_SENTINEL)) {
            return parseBinary(data, source);
        }
        try {
            return parseAscii(new java.io.ByteArrayInputStream(data), source);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e); // a byte array does not fail
        }
    }

    /**
     * Reads a drawing file: an ASCII one line by line from the stream, never as one string (the
     * values are kept as bytes, about 2.5 times the file's size for a drawing of LINEs), a
     * binary one whole.
     */
    static DxfTags parse(java.nio.file.Path file, String source) throws DxfException, java.io.IOException {
        try (java.io.InputStream in = java.nio.file.Files.newInputStream(file)) {
            byte[] head = in.readNBytes(BINARY_SENTINEL.length);
            if (Arrays.equals(head, BINARY_SENTINEL)) {
                return parseBinary(java.nio.file.Files.readAllBytes(file), source);
            }
            return parseAscii(new java.io.SequenceInputStream(new java.io.ByteArrayInputStream(head), in), source);
        }
    }

    /** The lines of a byte stream, each without its line feed. */
    private static final class Lines {
        private final java.io.InputStream in;
        private final byte[] buf = new byte[1 << 16];
        private int pos;
        private int lim;
        byte[] line = new byte[256];
        int len;
        /** The last line read ended with a line feed. */
        boolean terminated;

        Lines(java.io.InputStream in) {
            this.in = in;
        }

        private boolean fill() throws java.io.IOException {
            if (pos < lim) {
                return true;
            }
            int n = in.read(buf, 0, buf.length);
            pos = 0;
            lim = Math.max(0, n);
            return n > 0;
        }

        /** Reads the next line; false when the stream has no more bytes. */
        boolean next() throws java.io.IOException {
            len = 0;
            terminated = false;
            if (!fill()) {
                return false;
            }
            while (true) {
                int s = pos;
                while (pos < lim && buf[pos] != '\n') {
                    pos++;
                }
                int n = pos - s;
                if (len + n > line.length) {
                    line = Arrays.copyOf(line, Math.max(len + n, line.length * 2));
                }
                System.arraycopy(buf, s, line, len, n);
                len += n;
                if (pos < lim) {
                    pos++;
                    terminated = true;
                    return true;
                }
                if (!fill()) {
                    return true;
                }
            }
        }

        /** More bytes follow. */
        boolean more() throws java.io.IOException {
            return fill();
        }
    }

    private static DxfTags parseAscii(java.io.InputStream stream, String source)
            throws DxfException, java.io.IOException {
        DxfTags t = new DxfTags(source, false);
        Lines in = new Lines(stream);
        int line = 0;
        boolean first = true;
        while (in.next()) {
            int codeLine = ++line;
            byte[] text = in.line;
            int a = 0;
            int b = in.len;
            if (first && b >= 3 && (text[0] & 0xFF) == 0xEF && (text[1] & 0xFF) == 0xBB && (text[2] & 0xFF) == 0xBF) {
                a = 3; // the byte order mark
            }
            first = false;
            while (a < b && (text[a] & 0xFF) <= ' ') {
                a++;
            }
            while (b > a && (text[b - 1] & 0xFF) <= ' ') {
                b--;
            }
            if (a == b && !in.more()) {
                break;
            }
            int code = smallInt(text, a, b);
            if (code < 0) {
                code = code(new String(text, a, b - a, StandardCharsets.ISO_8859_1), t.size == 0, source, codeLine);
            }
            if (!in.terminated) {
                throw new DxfException(source, codeLine, "group code " + code + " has no value line (file truncated)");
            }
            ++line;
            in.next();
            int va = 0;
            int end = in.len;
            while (va < end && (in.line[va] & 0xFF) <= ' ') {
                va++;
            }
            while (end > va && (in.line[end - 1] & 0xFF) <= ' ') {
                end--;
            }
            t.add(code, in.line, va, end - va, 0);
            if (code == 0 && t.valueIs(t.size - 1, "EOF")) {
                break;
            }
        }
        if (t.size == 0) {
            throw new DxfException(source, 1, "not a DXF file: empty");
        }
        t.requireEof(line);
        return t;
    }

    private static int code(String codeText, boolean first, String source, int codeLine) throws DxfException {
        try {
            return Integer.parseInt(codeText);
        } catch (NumberFormatException ex) {
            if (first) {
                throw new DxfException(
                        source,
                        codeLine,
                        "not a DXF file: expected a group code (an integer), found '" + abbreviate(codeText) + "'");
            }
            throw new DxfException(
                    source, codeLine, "expected a group code (an integer), found '" + abbreviate(codeText) + "'");
        }
    }

    /** The digits text[a, b) as an int when they are 1 to 9 plain digits, else -1. */
    private static int smallInt(byte[] text, int a, int b) {
        if (b <= a || b - a > 9) {
            return -1;
        }
        int v = 0;
        for (int i = a; i < b; i++) {
            int c = text[i];
            if (c < '0' || c > '9') {
                return -1;
            }
            v = v * 10 + (c - '0');
        }
        return v;
    }

    private static String abbreviate(String s) {
        return s.length() > 40 ? s.substring(0, 40) + "..." : s;
    }

    private static DxfTags parseBinary(byte[] data, String source) throws DxfException {
        DxfTags t = new DxfTags(source, true);
        ByteBuffer b = ByteBuffer.wrap(data).order(ByteOrder.LITTLE_ENDIAN);
        int pos = BINARY_SENTINEL.length;
        // R12 writes one-byte group codes, R13 and later two bytes: the first tag is (0, SECTION)
        boolean wide = data.length > pos + 1 && data[pos] == 0 && data[pos + 1] == 0;
        try {
            while (pos < data.length) {
                int at = pos;
                int code;
                if (wide) {
                    code = b.getShort(pos) & 0xFFFF;
                    pos += 2;
                } else {
                    code = data[pos] & 0xFF;
                    pos += 1;
                    if (code == 255) {
                        code = b.getShort(pos) & 0xFFFF;
                        pos += 2;
                    }
                }
                String value;
                char type = type(code);
                switch (type) {
                    case 's' -> {
                        int z = pos;
                        while (z < data.length && data[z] != 0) {
                            z++;
                        }
                        if (z >= data.length) {
                            throw new DxfException(
                                    source, at, "binary DXF string of group " + code + " is not terminated");
                        }
                        value = new String(data, pos, z - pos, StandardCharsets.UTF_8);
                        pos = z + 1;
                    }
                    case 'x' -> { // binary chunk: a length byte and the bytes
                        int len = data[pos] & 0xFF;
                        pos += 1 + len;
                        value = "";
                    }
                    default -> { // a number of the type's fixed width, little-endian
                        value = switch (type) {
                            case 'd' -> Double.toString(b.getDouble(pos));
                            case 'h' -> Integer.toString(b.getShort(pos));
                            case 'i' -> Integer.toString(b.getInt(pos));
                            case 'l' -> Long.toString(b.getLong(pos));
                            default -> Integer.toString(data[pos] & 0xFF);
                        };
                        pos += switch (type) {
                            case 'd', 'l' -> 8;
                            case 'i' -> 4;
                            case 'h' -> 2;
                            default -> 1;
                        };
                    }
                }
                t.add(code, value, at);
                if (code == 0 && value.equals("EOF")) {
                    break;
                }
            }
        } catch (IndexOutOfBoundsException e) {
            throw new DxfException(source, data.length, "binary DXF ends in the middle of a group (file truncated)");
        }
        t.requireEof(data.length);
        return t;
    }

    /**
     * The group codes whose binary value is not a string, as the DXF reference lists them: the
     * first code, the last code and the type (d double, h int16, i int32, l int64, b byte, x
     * chunk). Every other code holds a string.
     */
    private static final int[][] NON_STRING_CODES = {
        {10, 59, 'd'},
        {60, 79, 'h'},
        {90, 99, 'i'},
        {110, 149, 'd'},
        {160, 169, 'l'},
        {170, 179, 'h'},
        {210, 239, 'd'},
        {270, 289, 'h'},
        {290, 299, 'b'},
        {310, 319, 'x'},
        {370, 389, 'h'},
        {400, 409, 'h'},
        {420, 429, 'i'},
        {440, 459, 'i'},
        {460, 469, 'd'},
        {1004, 1004, 'x'},
        {1010, 1059, 'd'},
        {1060, 1070, 'h'},
        {1071, 1071, 'i'},
    };

    /** The binary value type of a group code: s string, d double, h int16, i int32, l int64, b byte, x chunk. */
    private static char type(int c) {
        for (int[] range : NON_STRING_CODES) {
            if (c >= range[0] && c <= range[1]) {
                return (char) range[2];
            }
        }
        return 's';
    }
}
