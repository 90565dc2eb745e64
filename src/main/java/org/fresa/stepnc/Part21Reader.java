package org.fresa.stepnc;

import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.fresa.model.CamInputException;
import org.fresa.model.FileChecks;
import org.fresa.stepnc.Part21Lexer.Tok;

/**
 * Reads an ISO 10303-21 exchange structure (editions 1 to 3): header section, optional anchor
 * and reference sections (skipped), one or more data sections with simple and complex instances.
 * Streams the input; what stays in memory is the instance graph.
 *
 * <p>Faults are {@link StepParseException}s with line and column: syntax errors, a truncated
 * file, an instance name defined twice, a reference to an instance that is not defined, nesting
 * deeper than {@link #MAX_DEPTH}.
 */
public final class Part21Reader {

    /**
     * Deepest nesting of lists and typed parameters accepted; deeper input is refused. Real files
     * nest a few levels; 256 keeps the recursive descent well inside a 512 KiB thread stack.
     */
    public static final int MAX_DEPTH = 256;

    private final Part21Lexer lx;
    private final String source;
    private final InstanceStore store = new InstanceStore();
    private final PendingRefs pending = new PendingRefs();

    private Part21Reader(Reader in, String source) {
        this.lx = new Part21Lexer(in, source);
        this.source = source;
    }

    /**
     * Reads a file (UTF-8; bytes that are not UTF-8 become U+FFFD inside strings; a byte order
     * mark at the start is skipped).
     *
     * @throws StepParseException also for a path that is not a regular file, or a file larger
     *     than {@link #maxFileBytes()}
     */
    public static StepFile read(Path file) throws IOException, StepParseException {
        try {
            FileChecks.requireInput(file, "a Part 21 file", maxFileBytes());
        } catch (StepParseException e) {
            throw e;
        } catch (CamInputException e) {
            throw new StepParseException(e.source(), 0, 0, 0, e.problem());
        }
        try (InputStream in = Files.newInputStream(file)) {
            return read(
                    in,
                    file.getFileName() == null
                            ? file.toString()
                            : file.getFileName().toString());
        }
    }

    /**
     * The largest file read: the text streams through, but its instance graph stays in memory,
     * about four times the file's size, so a quarter of the Java heap (128 MB in 512 MB).
     */
    public static long maxFileBytes() {
        return FileChecks.heapShare(4);
    }

    public static StepFile read(InputStream in, String source) throws IOException, StepParseException {
        var decoder = StandardCharsets.UTF_8
                .newDecoder()
                .onMalformedInput(CodingErrorAction.REPLACE)
                .onUnmappableCharacter(CodingErrorAction.REPLACE);
        return read(new InputStreamReader(in, decoder), source);
    }

    /**
     * @param source the name used in messages (usually the file name)
     */
    public static StepFile read(Reader in, String source) throws IOException, StepParseException {
        return new Part21Reader(in, source).file();
    }

    private StepFile file() throws IOException, StepParseException {
        lx.next();
        expectKeyword("ISO-10303-21", "ISO-10303-21; (the first keyword of a Part 21 file)");
        expect(Tok.SEMICOLON, "';' after ISO-10303-21");
        expectKeyword("HEADER", "the header section (HEADER;)");
        expect(Tok.SEMICOLON, "';' after HEADER");
        List<StepRecord> header = new ArrayList<>();
        while (!(lx.tok == Tok.KEYWORD && lx.text.equals("ENDSEC"))) {
            if (lx.tok != Tok.KEYWORD) {
                throw unexpected("a header entity such as FILE_NAME(...) or ENDSEC");
            }
            header.add(simpleRecord(0));
            expect(Tok.SEMICOLON, "';' after a header entity");
        }
        lx.next();
        expect(Tok.SEMICOLON, "';' after ENDSEC");
        boolean sawData = false;
        while (true) {
            if (lx.tok != Tok.KEYWORD) {
                throw unexpected("DATA, ENDSEC or END-ISO-10303-21");
            }
            switch (lx.text) {
                case "DATA" -> {
                    dataSection();
                    sawData = true;
                }
                case "ANCHOR", "REFERENCE", "SIGNATURE" -> skipSection();
                case "END-ISO-10303-21" -> {
                    lx.next();
                    if (lx.tok != Tok.SEMICOLON) {
                        throw unexpected("';' after END-ISO-10303-21");
                    }
                    if (!sawData) {
                        throw lx.errorHere("the file has no DATA section");
                    }
                    pending.check();
                    return new StepFile(source, header, store);
                }
                default -> throw unexpected("DATA, ENDSEC or END-ISO-10303-21");
            }
        }
    }

    private void dataSection() throws IOException, StepParseException {
        lx.next();
        if (lx.tok == Tok.LPAREN) {
            // edition 3: DATA('name', ('SCHEMA')); the parameters do not matter here
            aggregate(0);
        }
        expect(Tok.SEMICOLON, "';' after DATA");
        while (true) {
            if (lx.tok == Tok.INSTANCE) {
                instance();
            } else if (lx.tok == Tok.KEYWORD && lx.text.equals("ENDSEC")) {
                lx.next();
                expect(Tok.SEMICOLON, "';' after ENDSEC");
                return;
            } else if (lx.tok == Tok.EOF) {
                throw lx.errorHere(
                        "the file ends inside the DATA section (truncated? ENDSEC; and END-ISO-10303-21; are missing)");
            } else {
                throw unexpected("an instance (#n = ...;) or ENDSEC");
            }
        }
    }

    private void skipSection() throws IOException, StepParseException {
        while (!(lx.tok == Tok.KEYWORD && lx.text.equals("ENDSEC"))) {
            if (lx.tok == Tok.EOF) {
                throw lx.errorHere("the file ends before ENDSEC");
            }
            lx.next();
        }
        lx.next();
        expect(Tok.SEMICOLON, "';' after ENDSEC");
    }

    private void instance() throws IOException, StepParseException {
        long id = lx.longValue;
        int line = lx.tokLine;
        int col = lx.tokCol;
        if (id == 0) {
            throw lx.errorHere("instance name #0 is not allowed (names start at #1)");
        }
        lx.currentInstance = id;
        lx.next();
        expect(Tok.EQUALS, "'=' after the instance name");
        int earlier = store.indexOf(id);
        if (earlier >= 0) {
            throw new StepParseException(
                    source,
                    line,
                    col,
                    id,
                    "instance name #" + id + " is defined twice (first at line " + store.lineAt(earlier) + ")");
        }
        if (lx.tok == Tok.KEYWORD) {
            store.beginInstance(id, line, col, false);
            encodeRecord(0, id);
        } else if (lx.tok == Tok.LPAREN) {
            store.beginInstance(id, line, col, true);
            lx.next();
            int records = 0;
            while (lx.tok == Tok.KEYWORD) {
                encodeRecord(1, id);
                records++;
            }
            if (records == 0) {
                throw unexpected("an entity name in the complex instance");
            }
            expect(Tok.RPAREN, "')' closing the complex instance");
        } else {
            throw unexpected("an entity name or '(' of a complex instance");
        }
        expect(Tok.SEMICOLON, "';' ending the instance");
        lx.currentInstance = 0;
    }

    // ---- the data section, written straight into the compact store ----

    private void encodeRecord(int depth, long self) throws IOException, StepParseException {
        String type = lx.text;
        lx.next();
        if (lx.tok != Tok.LPAREN) {
            throw unexpected("'(' after " + type);
        }
        store.putString(InstanceStore.RECORD, type);
        encodeAggregate(depth, self);
    }

    private void encodeAggregate(int depth, long self) throws IOException, StepParseException {
        if (depth >= MAX_DEPTH) {
            throw lx.errorHere("lists are nested more than " + MAX_DEPTH + " deep");
        }
        store.put(InstanceStore.BEGIN);
        lx.next();
        if (lx.tok == Tok.RPAREN) {
            lx.next();
            store.put(InstanceStore.END);
            return;
        }
        while (true) {
            encodeParameter(depth + 1, self);
            if (lx.tok == Tok.COMMA) {
                lx.next();
            } else if (lx.tok == Tok.RPAREN) {
                lx.next();
                store.put(InstanceStore.END);
                return;
            } else {
                throw unexpected("',' or ')' in a parameter list");
            }
        }
    }

    private void encodeParameter(int depth, long self) throws IOException, StepParseException {
        switch (lx.tok) {
            case DOLLAR -> store.put(InstanceStore.UNSET);
            case STAR -> store.put(InstanceStore.DERIVED);
            case INTEGER -> store.putSigned(InstanceStore.INT, lx.longValue);
            case REAL -> store.putReal(lx.doubleValue);
            case STRING -> store.putString(InstanceStore.TEXT, lx.text);
            case ENUMERATION -> store.putString(InstanceStore.ENUM, lx.text);
            case BINARY -> store.putString(InstanceStore.BINARY, lx.text);
            case INSTANCE -> store.putSigned(InstanceStore.REF, reference() - self);
            case LPAREN -> {
                encodeAggregate(depth, self);
                return;
            }
            case KEYWORD -> {
                String type = typeName(depth);
                store.putString(InstanceStore.TYPED, type);
                encodeParameter(depth + 1, self);
                expect(Tok.RPAREN, "')' closing " + type + "(...)");
                return;
            }
            case EOF -> throw lx.errorHere("the file ends inside an instance (truncated?)");
            default -> throw unexpected("a parameter ($, *, number, 'string', .ENUM., #ref, list or TYPE(value))");
        }
        lx.next();
    }

    // ---- the header, read as values ----

    /** KEYWORD '(' [params] ')', the current token being the keyword. */
    private StepRecord simpleRecord(int depth) throws IOException, StepParseException {
        String type = lx.text;
        lx.next();
        if (lx.tok != Tok.LPAREN) {
            throw unexpected("'(' after " + type);
        }
        return new StepRecord(type, ((StepValue.Aggregate) aggregate(depth)).items());
    }

    /** '(' [param {',' param}] ')', the current token being '('; leaves the token after ')'. */
    private StepValue aggregate(int depth) throws IOException, StepParseException {
        if (depth >= MAX_DEPTH) {
            throw lx.errorHere("lists are nested more than " + MAX_DEPTH + " deep");
        }
        lx.next();
        List<StepValue> items = new ArrayList<>();
        if (lx.tok == Tok.RPAREN) {
            lx.next();
            return new StepValue.Aggregate(items);
        }
        while (true) {
            items.add(parameter(depth + 1));
            if (lx.tok == Tok.COMMA) {
                lx.next();
            } else if (lx.tok == Tok.RPAREN) {
                lx.next();
                return new StepValue.Aggregate(items);
            } else {
                throw unexpected("',' or ')' in a parameter list");
            }
        }
    }

    /** The instance name of the current #ref token, noted as pending while it is not yet defined. */
    private long reference() throws StepParseException {
        long id = lx.longValue;
        if (id == 0) {
            throw lx.errorHere("#0 is not an instance name");
        }
        if (store.indexOf(id) < 0) {
            pending.add(id, lx.currentInstance, lx.tokLine, lx.tokCol);
        }
        return id;
    }

    /** The type name of a typed parameter at this depth, read up to and including its '('. */
    private String typeName(int depth) throws IOException, StepParseException {
        String type = lx.text;
        if (depth >= MAX_DEPTH) {
            throw lx.errorHere("typed parameters are nested more than " + MAX_DEPTH + " deep");
        }
        lx.next();
        expect(Tok.LPAREN, "'(' after the type name " + type);
        return type;
    }

    private StepValue parameter(int depth) throws IOException, StepParseException {
        StepValue v;
        switch (lx.tok) {
            case DOLLAR -> v = StepValue.UNSET;
            case STAR -> v = StepValue.DERIVED;
            case INTEGER -> v = new StepValue.Int(lx.longValue);
            case REAL -> v = new StepValue.Real(lx.doubleValue);
            case STRING -> v = new StepValue.Text(lx.text);
            case ENUMERATION -> v = new StepValue.Enumeration(lx.text);
            case BINARY -> v = new StepValue.Binary(lx.text);
            case INSTANCE -> v = new StepValue.Ref(reference());
            case LPAREN -> {
                return aggregate(depth);
            }
            case KEYWORD -> {
                String type = typeName(depth);
                StepValue inner = parameter(depth + 1);
                expect(Tok.RPAREN, "')' closing " + type + "(...)");
                return new StepValue.Typed(type, inner);
            }
            case EOF -> throw lx.errorHere("the file ends inside an instance (truncated?)");
            default -> throw unexpected("a parameter ($, *, number, 'string', .ENUM., #ref, list or TYPE(value))");
        }
        lx.next();
        return v;
    }

    private void expect(Tok t, String what) throws IOException, StepParseException {
        if (lx.tok != t) {
            throw unexpected(what);
        }
        lx.next();
    }

    private void expectKeyword(String kw, String what) throws IOException, StepParseException {
        if (lx.tok != Tok.KEYWORD || !lx.text.equals(kw)) {
            throw unexpected(what);
        }
        lx.next();
    }

    private StepParseException unexpected(String expected) {
        String found = switch (lx.tok) {
            case EOF -> "the end of the file";
            case STRING -> "a string";
            case KEYWORD -> shorten(lx.text);
            case INSTANCE -> "#" + lx.longValue;
            default -> "'" + shorten(lx.tokenText()) + "'";
        };
        return lx.errorHere("expected " + expected + ", found " + found);
    }

    private static String shorten(String s) {
        return s.length() > 40 ? s.substring(0, 37) + "..." : s;
    }

    /** Forward references, checked at the end; primitive arrays keep large files lean. */
    private final class PendingRefs {
        private long[] target = new long[256];
        private long[] from = new long[256];
        private int[] lines = new int[256];
        private int[] cols = new int[256];
        private int n;

        void add(long t, long f, int l, int c) {
            if (n == target.length) {
                purgeResolved();
                if (n * 2 > target.length) {
                    int m = target.length * 2;
                    target = Arrays.copyOf(target, m);
                    from = Arrays.copyOf(from, m);
                    lines = Arrays.copyOf(lines, m);
                    cols = Arrays.copyOf(cols, m);
                }
            }
            target[n] = t;
            from[n] = f;
            lines[n] = l;
            cols[n] = c;
            n++;
        }

        /** Forgets the references whose target has been defined since, keeping the order. */
        private void purgeResolved() {
            int k = 0;
            for (int i = 0; i < n; i++) {
                if (store.indexOf(target[i]) < 0) {
                    target[k] = target[i];
                    from[k] = from[i];
                    lines[k] = lines[i];
                    cols[k] = cols[i];
                    k++;
                }
            }
            n = k;
        }

        void check() throws StepParseException {
            for (int i = 0; i < n; i++) {
                if (store.indexOf(target[i]) < 0) {
                    throw new StepParseException(
                            source,
                            lines[i],
                            cols[i],
                            from[i],
                            "refers to #" + target[i] + ", which is not defined in the file");
                }
            }
            n = 0;
        }
    }
}
