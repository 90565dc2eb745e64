package org.fresa.stepnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringReader;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class Part21ReaderTest {

    private static final String HEAD = "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\n"
            + "FILE_NAME('x','2020',(''),(''),'','','');\nFILE_SCHEMA(('MACHINING_SCHEMA'));\nENDSEC;\n";

    static StepFile parse(String text) throws IOException, StepParseException {
        return Part21Reader.read(new StringReader(text), "test.stp");
    }

    static StepFile data(String instances) throws IOException, StepParseException {
        return parse(HEAD + "DATA;\n" + instances + "\nENDSEC;\nEND-ISO-10303-21;\n");
    }

    static StepValue param(String value) throws IOException, StepParseException {
        return data("#1=X(" + value + ");").instance(1).orElseThrow().record().param(0);
    }

    static StepParseException failure(String text) {
        return assertThrows(StepParseException.class, () -> parse(text));
    }

    @Test
    void headerRecordsAndSchemaNamesAreRead() throws Exception {
        StepFile f = data("#1=A();");
        assertEquals(List.of("MACHINING_SCHEMA"), f.schemas());
        assertEquals(3, f.header().size());
        assertEquals("FILE_NAME", f.header().get(1).type());
    }

    @Test
    void aSimpleInstanceKeepsItsNameTypeAndPosition() throws Exception {
        StepFile f = data("#42= CARTESIAN_POINT('',(1.,2.,3.));");
        StepInstance i = f.instance(42).orElseThrow();
        assertEquals("CARTESIAN_POINT", i.type());
        assertFalse(i.isComplex());
        assertEquals(8, i.line());
        assertEquals(1, i.column());
        assertEquals("(1.0,2.0,3.0)", i.record().param(1).toString());
    }

    @Test
    void aComplexInstanceKeepsEachPartialRecordInOrder() throws Exception {
        StepFile f = data("#7=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.));");
        StepInstance i = f.instance(7).orElseThrow();
        assertTrue(i.isComplex());
        assertEquals("LENGTH_UNIT+NAMED_UNIT+SI_UNIT", i.type());
        assertEquals(StepValue.DERIVED, i.part("NAMED_UNIT").orElseThrow().param(0));
        assertEquals(
                new StepValue.Enumeration("METRE"),
                i.part("SI_UNIT").orElseThrow().param(1));
    }

    @Test
    void aTypedParameterKeepsItsTypeName() throws Exception {
        StepValue v = param("LENGTH_MEASURE(2.)");
        assertEquals(new StepValue.Typed("LENGTH_MEASURE", new StepValue.Real(2.0)), v);
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            .T.          | .T.
            .CONVENTIONAL. | .CONVENTIONAL.
            $            | $
            *            | *
            12           | 12
            -7           | -7
            +3           | 3
            1.5E3        | 1500.0
            -2.5e-1      | -0.25
            0.           | 0.0
            -0.5         | -0.5
            ()           | ()
            ((1,2),(3))  | ((1,2),(3))
            """)
    void eachSimpleParameterKindIsRead(String written, String expected) throws Exception {
        StepFile f = data("#1=X(" + written + ");");
        assertEquals(expected, f.instance(1).orElseThrow().record().param(0).toString());
    }

    @Test
    void aBinaryKeepsItsHexDigits() throws Exception {
        assertEquals(new StepValue.Binary("0FA"), param("\"0FA\""));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', quoteCharacter = '"', textBlock = """
            'it''s'              | it's
            'a\\\\b'             | a\\b
            'caf\\X\\E9'         | café
            '\\X2\\00E900E8\\X0\\' | éè
            '\\X4\\0001F600\\X0\\' | 😀
            '\\S\\i'             | é
            '\\PB\\\\S\\i'       | é
            'C:\\temp'           | C:\\temp
            """)
    void stringEscapesAreDecoded(String written, String expected) throws Exception {
        assertEquals(new StepValue.Text(expected), param(written));
    }

    @Test
    void aLineBreakInsideAStringIsNotPartOfIt() throws Exception {
        assertEquals(new StepValue.Text("abcdef"), param("'abc\ndef'"));
    }

    @Test
    void commentsMayStandWhereverWhitespaceMay() throws Exception {
        StepFile f = parse("/* before */ISO-10303-21;/*a*/HEADER;FILE_DESCRIPTION(/* d */(''),'2;1');"
                + "FILE_NAME('','',(''),(''),'','','');FILE_SCHEMA(('S'));ENDSEC;DATA;"
                + "#1 /* x */ = /* y */ A(/* z */ 1 /* w */, #2 /* v */);/* between */#2=B();"
                + "ENDSEC;END-ISO-10303-21;/* after */");
        assertEquals(2, f.instances().size());
    }

    @Test
    void forwardAndBackwardReferencesResolve() throws Exception {
        StepFile f = data("#1=A(#3);#2=B();#3=C(#2,#1);");
        assertEquals(new StepValue.Ref(3), f.instance(1).orElseThrow().record().param(0));
        assertEquals(3, f.instances().size());
    }

    @Test
    void lowerCaseKeywordsAreAccepted() throws Exception {
        assertEquals(
                "CARTESIAN_POINT",
                data("#1=cartesian_point('',(0.,0.));")
                        .instance(1)
                        .orElseThrow()
                        .type());
    }

    @Test
    void severalDataSectionsAreRead() throws Exception {
        StepFile f = parse(HEAD + "DATA;#1=A(#2);ENDSEC;DATA('second',('S'));#2=B();ENDSEC;END-ISO-10303-21;");
        assertEquals(2, f.instances().size());
    }

    @Test
    void instanceNamesUpTo64BitsAreAccepted() throws Exception {
        StepFile f = data("#1=X(#9223372036854775807);#9223372036854775807=Y();");
        assertEquals(
                new StepValue.Ref(Long.MAX_VALUE),
                f.instance(1).orElseThrow().record().param(0));
    }

    @Test
    void anInstanceNameBeyond64BitsIsRefused() {
        StepParseException e = failure(HEAD + "DATA;\n#9223372036854775808=A();\nENDSEC;END-ISO-10303-21;");
        assertTrue(e.getMessage().contains("larger than 64 bits"), e.getMessage());
        assertEquals(8, e.line().orElseThrow());
    }

    @Test
    void aDanglingReferenceNamesItsLineAndInstance() {
        StepParseException e = failure(HEAD + "DATA;\n#1=A();\n#2=B(1.,\n  #77);\nENDSEC;END-ISO-10303-21;");
        assertEquals(10, e.line().orElseThrow());
        assertEquals(3, e.column().orElseThrow());
        assertEquals(2, e.instanceId().orElseThrow());
        assertTrue(e.getMessage().contains("#77"), e.getMessage());
    }

    @Test
    void aDuplicateInstanceNameNamesBothLines() {
        StepParseException e = failure(HEAD + "DATA;\n#1=A();\n#1=B();\nENDSEC;END-ISO-10303-21;");
        assertEquals(9, e.line().orElseThrow());
        assertTrue(e.getMessage().contains("first at line 8"), e.getMessage());
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', quoteCharacter = '`', textBlock = """
            expected ',' or ')'              | #1=A(1,2;
            expected ';' ending the instance | #1=A(1,2));
            expected ',' or ')'              | #1=A((1,2);
            expected ',' or ')'              | #1=A(1 2);
            enumeration                      | #1=A(.T);
            string opened here is not closed | #1=A('open);
            exponent                         | #1=A(1.E);
            expected ',' or ')'              | #1=A(1E999.);
            out of range                     | #1=A(1.0E999);
            '#' must be followed             | #1=A(#);
            unexpected character             | #1=A(?);
            '=' after the instance name      | #1 A();
            #0                               | #0=A();
            hexadecimal                      | #1=A("0G");
            comment opened here              | #1=A(1); /* no end
            """)
    void syntaxErrorsSayWhatWasExpected(String expected, String instance) {
        StepParseException e = failure(HEAD + "DATA;\n" + instance + "\nENDSEC;\nEND-ISO-10303-21;\n");
        assertTrue(e.getMessage().contains(expected), e.getMessage());
        assertEquals(8, e.line().orElseThrow(), e.getMessage());
    }

    @Test
    void aTruncatedFileIsRefusedAtItsEnd() {
        StepParseException e = failure(HEAD + "DATA;\n#1=A(1,\n");
        assertEquals(9, e.line().orElseThrow());
    }

    @Test
    void aFileWithoutTheClosingKeywordIsRefused() {
        StepParseException e = failure(HEAD + "DATA;\n#1=A();\nENDSEC;\n");
        assertTrue(e.getMessage().contains("END-ISO-10303-21"), e.getMessage());
    }

    @Test
    void aFileThatIsNotPart21SaysSoAtLineOne() {
        StepParseException e = failure("0 SECTION\n2 HEADER\n");
        assertEquals(1, e.line().orElseThrow());
        assertTrue(e.getMessage().contains("ISO-10303-21"), e.getMessage());
    }

    @Test
    void nestingDeeperThanTheLimitIsRefusedWithoutAStackOverflow() {
        int n = Part21Reader.MAX_DEPTH + 5;
        String deep = "(".repeat(n) + ")".repeat(n);
        StepParseException e = failure(HEAD + "DATA;\n#1=A(" + deep + ");\nENDSEC;END-ISO-10303-21;");
        assertTrue(e.getMessage().contains("nested more than"), e.getMessage());
        String typed = "T(".repeat(n) + "1" + ")".repeat(n);
        e = failure(HEAD + "DATA;\n#1=A(" + typed + ");\nENDSEC;END-ISO-10303-21;");
        assertTrue(e.getMessage().contains("nested more than"), e.getMessage());
    }

    @Test
    void nestingUpToTheLimitIsAccepted() throws Exception {
        int n = Part21Reader.MAX_DEPTH - 5;
        StepValue v = param("(".repeat(n) + "1" + ")".repeat(n));
        assertInstanceOf(StepValue.Aggregate.class, v);
    }

    @Test
    void anchorAndReferenceSectionsAreSkipped() throws Exception {
        StepFile f = parse(HEAD + "ANCHOR;ENDSEC;REFERENCE;ENDSEC;DATA;#1=A();ENDSEC;END-ISO-10303-21;");
        assertEquals(1, f.instances().size());
    }

    @Test
    void realsReadExactlyAsParseDoubleReadsThem() throws Exception {
        // the lexer's fast path for short decimals must round exactly like the JDK
        java.util.Random rnd = new java.util.Random(11);
        StringBuilder sb = new StringBuilder();
        List<String> written = new java.util.ArrayList<>();
        for (int i = 0; i < 2000; i++) {
            String mantissa = Long.toString(Math.abs(rnd.nextLong()) % (i % 2 == 0 ? 100_000_000L : Long.MAX_VALUE));
            int point = rnd.nextInt(mantissa.length() + 1);
            String w = (rnd.nextBoolean() ? "-" : "") + mantissa.substring(0, Math.max(1, point)) + "."
                    + mantissa.substring(Math.max(1, point))
                    + (i % 3 == 0 ? "E" + (rnd.nextInt(60) - 30) : "");
            written.add(w);
            sb.append("#").append(i + 1).append("=X(").append(w).append(");");
        }
        StepFile f = data(sb.toString());
        for (int i = 0; i < written.size(); i++) {
            assertEquals(
                    new StepValue.Real(Double.parseDouble(written.get(i))),
                    f.instance(i + 1).orElseThrow().record().param(0),
                    written.get(i));
        }
    }

    @Test
    void realsWithSixteenAndSeventeenDigitsReadAsParseDoubleReadsThem() throws Exception {
        // the fast path takes mantissas up to 2^53 (most 16-digit ones, as writers print doubles);
        // the ones just above 2^53 and with 17 digits must go the slow way and agree as well
        java.util.Random rnd = new java.util.Random(53);
        long twoTo53 = 1L << 53;
        StringBuilder sb = new StringBuilder();
        List<String> written = new java.util.ArrayList<>();
        for (int i = 0; i < 3000; i++) {
            long m = switch (i % 4) {
                case 0 -> twoTo53 - rnd.nextInt(1000);
                case 1 -> twoTo53 + rnd.nextInt(1000);
                case 2 -> 1_000_000_000_000_000L + (Math.abs(rnd.nextLong()) % (twoTo53 - 1_000_000_000_000_000L));
                default -> 10_000_000_000_000_000L + (Math.abs(rnd.nextLong()) % 90_000_000_000_000_000L);
            };
            String digits = Long.toString(m);
            int point = 1 + rnd.nextInt(digits.length());
            String w = (i % 5 == 0 ? "-" : "")
                    + (i % 7 == 0 ? "0." + digits : digits.substring(0, point) + "." + digits.substring(point))
                    + (i % 3 == 0 ? "E" + (rnd.nextInt(50) - 25) : "");
            written.add(w);
            sb.append("#").append(i + 1).append("=X(").append(w).append(");");
        }
        StepFile f = data(sb.toString());
        for (int i = 0; i < written.size(); i++) {
            assertEquals(
                    new StepValue.Real(Double.parseDouble(written.get(i))),
                    f.instance(i + 1).orElseThrow().record().param(0),
                    written.get(i));
        }
    }

    /** Hands out at most one character per read, so every token straddles a refill of the lexer's buffer. */
    private static final class Trickle extends java.io.Reader {
        private final String text;
        private int at;

        Trickle(String text) {
            this.text = text;
        }

        @Override
        public int read(char[] cbuf, int off, int len) {
            if (at == text.length()) {
                return -1;
            }
            cbuf[off] = text.charAt(at++);
            return 1;
        }

        @Override
        public void close() {}
    }

    @Test
    void aFileHandedOutOneCharacterAtATimeReadsAsAWholeOne() throws Exception {
        String text = java.nio.file.Files.readString(java.nio.file.Path.of("samples/stepnc/example2.stp"));
        StepFile whole = parse(text);
        StepFile trickled = Part21Reader.read(new Trickle(text), "test.stp");
        assertEquals(whole.header(), trickled.header());
        assertEquals(
                List.copyOf(whole.instances().values()),
                List.copyOf(trickled.instances().values()));
        String odd = HEAD + "DATA;\n#1=x_y-z('a''b\\X2\\00E9\\X0\\c',.t.,-1.5E+3,\"0F\",  \t#1);\n#2=A(12, /* c */ .";
        StepParseException a = assertThrows(StepParseException.class, () -> parse(odd));
        StepParseException b =
                assertThrows(StepParseException.class, () -> Part21Reader.read(new Trickle(odd), "test.stp"));
        assertEquals(a.getMessage(), b.getMessage());
    }
}
