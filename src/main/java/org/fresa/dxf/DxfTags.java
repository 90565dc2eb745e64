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
    int[] codes = new int[1024];
    String[] values = new String[1024];
    int[] lines = new int[1024];

    private DxfTags(String source, boolean binary) {
        this.source = source;
        this.binary = binary;
    }

    String where(int index) {
        int l = index < size ? lines[index] : (size > 0 ? lines[size - 1] : 0);
        return binary ? "byte " + l : "line " + l;
    }

    /** Where the value of tag index is: its line in ASCII (the line after the code). */
    String whereValue(int index) {
        return binary ? where(index) : "line " + (lines[index] + 1);
    }

    private void add(int code, String value, int line) {
        if (size == codes.length) {
            int n = size * 2;
            codes = Arrays.copyOf(codes, n);
            values = Arrays.copyOf(values, n);
            lines = Arrays.copyOf(lines, n);
        }
        codes[size] = code;
        values[size] = value;
        lines[size] = line;
        size++;
    }

    /** A drawing ends with (0, EOF): without it the file was cut short and its end is missing. */
    private void requireEof(int lastLine) throws DxfException {
        if (size > 0 && codes[size - 1] == 0 && values[size - 1].equals("EOF")) {
            return;
        }
        throw new DxfException(source, binary ? 0 : lastLine, (binary ? "byte " + lastLine + ": " : "")
                + "the drawing ends without its closing group 0 EOF (the file is truncated)");
    }

    static DxfTags parse(byte[] data, String source) throws DxfException {
        if (data.length >= BINARY_SENTINEL.length
                && Arrays.equals(Arrays.copyOf(data, BINARY_SENTINEL.length), BINARY_SENTINEL)) {
            return parseBinary(data, source);
        }
        return parseAscii(decode(data), source);
    }

    private static String decode(byte[] data) {
        try {
            return StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(ByteBuffer.wrap(data)).toString();
        } catch (CharacterCodingException e) {
            // pre-2007 drawings are in the ANSI code page; names only, geometry is unaffected
            return new String(data, StandardCharsets.ISO_8859_1);
        }
    }

    private static DxfTags parseAscii(String text, String source) throws DxfException {
        DxfTags t = new DxfTags(source, false);
        int pos = 0;
        int n = text.length();
        int line = 0;
        if (n > 0 && text.charAt(0) == '\uFEFF') {
            pos = 1;
        }
        while (pos < n) {
            int codeLine = ++line;
            int e1 = text.indexOf('\n', pos);
            if (e1 < 0) {
                e1 = n;
            }
            int a = pos;
            int b = e1;
            while (a < b && text.charAt(a) <= ' ') {
                a++;
            }
            while (b > a && text.charAt(b - 1) <= ' ') {
                b--;
            }
            pos = e1 + 1;
            if (a == b && pos >= n) {
                break;
            }
            int code = smallInt(text, a, b);
            if (code < 0) {
                code = code(text.substring(a, b), t.size == 0, source, codeLine);
            }
            if (pos > n) {
                throw new DxfException(source, codeLine, "group code " + code + " has no value line (file truncated)");
            }
            ++line;
            int e2 = text.indexOf('\n', pos);
            if (e2 < 0) {
                e2 = n;
            }
            int end = e2;
            if (end > pos && text.charAt(end - 1) == '\r') {
                end--;
            }
            int va = pos;
            while (va < end && text.charAt(va) <= ' ') {
                va++;
            }
            while (end > va && text.charAt(end - 1) <= ' ') {
                end--;
            }
            String value = text.substring(va, end);
            pos = e2 + 1;
            t.add(code, value, codeLine);
            if (code == 0 && value.equals("EOF")) {
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
                throw new DxfException(source, codeLine, "not a DXF file: expected a group code (an integer), found '"
                        + abbreviate(codeText) + "'");
            }
            throw new DxfException(source, codeLine, "expected a group code (an integer), found '"
                    + abbreviate(codeText) + "'");
        }
    }

    /** The digits text[a, b) as an int when they are 1 to 9 plain digits, else -1. */
    private static int smallInt(String text, int a, int b) {
        if (b <= a || b - a > 9) {
            return -1;
        }
        int v = 0;
        for (int i = a; i < b; i++) {
            char c = text.charAt(i);
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
                switch (type(code)) {
                    case 's' -> {
                        int z = pos;
                        while (z < data.length && data[z] != 0) {
                            z++;
                        }
                        if (z >= data.length) {
                            throw new DxfException(source, at, "binary DXF string of group " + code + " is not terminated");
                        }
                        value = new String(data, pos, z - pos, StandardCharsets.UTF_8);
                        pos = z + 1;
                    }
                    case 'd' -> {
                        value = Double.toString(b.getDouble(pos));
                        pos += 8;
                    }
                    case 'h' -> {
                        value = Integer.toString(b.getShort(pos));
                        pos += 2;
                    }
                    case 'i' -> {
                        value = Integer.toString(b.getInt(pos));
                        pos += 4;
                    }
                    case 'l' -> {
                        value = Long.toString(b.getLong(pos));
                        pos += 8;
                    }
                    case 'b' -> {
                        value = Integer.toString(data[pos] & 0xFF);
                        pos += 1;
                    }
                    default -> { // binary chunk: a length byte and the bytes
                        int len = data[pos] & 0xFF;
                        pos += 1 + len;
                        value = "";
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

    /** The binary value type of a group code: s string, d double, h int16, i int32, l int64, b byte, x chunk. */
    private static char type(int c) {
        if (c <= 9) {
            return 's';
        }
        if (c <= 59) {
            return 'd';
        }
        if (c <= 79) {
            return 'h';
        }
        if (c >= 90 && c <= 99) {
            return 'i';
        }
        if (c >= 100 && c <= 109) {
            return 's';
        }
        if (c >= 110 && c <= 149) {
            return 'd';
        }
        if (c >= 160 && c <= 169) {
            return 'l';
        }
        if (c >= 170 && c <= 179) {
            return 'h';
        }
        if (c >= 210 && c <= 239) {
            return 'd';
        }
        if (c >= 270 && c <= 289) {
            return 'h';
        }
        if (c >= 290 && c <= 299) {
            return 'b';
        }
        if (c >= 300 && c <= 309) {
            return 's';
        }
        if (c >= 310 && c <= 319) {
            return 'x';
        }
        if (c >= 320 && c <= 369) {
            return 's';
        }
        if (c >= 370 && c <= 389) {
            return 'h';
        }
        if (c >= 390 && c <= 399) {
            return 's';
        }
        if (c >= 400 && c <= 409) {
            return 'h';
        }
        if (c >= 410 && c <= 419) {
            return 's';
        }
        if (c >= 420 && c <= 429) {
            return 'i';
        }
        if (c >= 430 && c <= 439) {
            return 's';
        }
        if (c >= 440 && c <= 459) {
            return 'i';
        }
        if (c >= 460 && c <= 469) {
            return 'd';
        }
        if (c >= 470 && c <= 481) {
            return 's';
        }
        if (c == 1004) {
            return 'x';
        }
        if (c >= 1010 && c <= 1059) {
            return 'd';
        }
        if (c >= 1060 && c <= 1070) {
            return 'h';
        }
        if (c == 1071) {
            return 'i';
        }
        return 's';
    }
}
