package org.fresa.stepnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.stream.Stream;
import org.fresa.testing.CorpusCheck;
import org.fresa.testing.TestInputs;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The token stream of real files: each token's kind, position, text and value, digested. The
 * digests were taken with the lexer of two number scanners (one inside the buffer, one across
 * its refills), so the one scanner kept must read every file as both did; a file handed out one
 * character at a time, every token across a refill, must read the same.
 */
class Part21LexerTest {

    /** SHA-256 of the token stream of each file, taken before the lexer kept one number scanner. */
    private static final Map<String, String> DIGESTS = Map.ofEntries(
            Map.entry("Cavidade.p21", "c0061e3d377148dace18f4a827b1caa1273a378b43b7a0e4c3cbeab837ee20eb"),
            Map.entry("FuroBaseArredondada.p21", "327ec55bbddde42ab6be7a725c01629ed3d63b09a4782382ac3ea9a292f708f9"),
            Map.entry("FuroBaseConica.p21", "1f7968e08b9e5595524fcaccc1e5ec71b5f4194919c03652a8d0356513a829f3"),
            Map.entry("FuroBaseEsferica.p21", "5e053bda5553861428c9eb6fc99c9581da64e7727134a992624f1ce238a2e47f"),
            Map.entry("FuroConico.p21", "a4aea785029ffbba41d778dc3607ffae3892da4164c2a99368807091bc27e83e"),
            Map.entry(
                    "OneHoleOneSlotReaderTest.p21", "ec560b314613c379dd8a30f8aadc801b5894c9f6583374f22fdcf24b91406734"),
            Map.entry("Ranhura.p21", "a2f33dbc59f66470cf57f32a82cd7d7bd9d526edf084d47c70526e8d72e3f148"),
            Map.entry("RanhuraPerfilBezier.p21", "f8a435eb553e8c57c8b63600a8c185c83295831a840bd7f34003f3bd0d124549"),
            Map.entry(
                    "RanhuraPerfilCircularParcial.p21",
                    "fb3c584fbb3777fb6d93d42fe5fde9e751462d63c64dbed9d5fbee660d4ae51c"),
            Map.entry("RanhuraPerfilRoundedU.p21", "ef5401e2d9afc32d037725dada93c306c9e60c25c281109ef770661ba3d682d8"),
            Map.entry("RanhuraPerfilUQuadrado.p21", "fff6275b90422600b0d6299eb1d213ec0f0c674233777fea5e872f4f31658654"),
            Map.entry("RanhuraPerfilVee.p21", "e8056570d69ecce098625a4718798daca91be6ba222bae2d49332c1cf33b5578"),
            Map.entry("STEP-NC 2HolesFile.p21", "bf88f1d7b4a680846825cd7f29bf82216c9a920400fb9a65674c392c39507d1b"),
            Map.entry("STEP-NC File.p21", "e3bb011f3112aeada9d62c9d2987e900ed4ed40a40d0d32c062bb1b8ba058055"),
            Map.entry("STEP-NC2DifHOLES.p21", "fe0d852a1dd4aca9ff339f33236f4024071cd42eff79de1029f5ddc18b9af25d"),
            Map.entry("STEP-NC_Slot1 File.p21", "29e313b43422eabc25331467e84c081ef0bd0341f93be9939d211b90b241d39d"),
            Map.entry("STEP-NC_pocket File.p21", "7620fc1161bad1d7b697ed00e0cab326662874e30a3f8334a23b2e2aa57e424f"),
            Map.entry("STEP-NC_pocket1 File.p21", "5c67afa42d004d963c5154632352454656d1c7d7e048a933a3ffbdba5bd8fe66"),
            Map.entry("STEP-NC_slot File.p21", "ac190bad3537e7a14662197165934fe46a89013494b4a672c8c95bf4bd3ba009"),
            Map.entry("aim-cc1-toolpaths.stp", "ff9106505aea9f16f69d5d5d87ea7cacf1e21ab22ea2d380e67be3a9608a50e1"),
            Map.entry("aim-header-only.stp", "4fa027b3d06fde7daa3b9f1c84509aa3cc754bf737f0bd842fe9c1c809b4208c"),
            // retaken by the one scanner when the plate's block was added to the file, which gave
            // c98a06d2b8ec1a080183c204d95daf2972d99b86dcab55e71bedf1f89a766873 before, with both scanners and with one
            Map.entry(
                    "aim-inch-hole-and-pocket.stp", "d25599434d8edd8b5eee8c44f4462a4211606ba3fd4a5271429dc4573bc2dc1c"),
            Map.entry(
                    "annexJ4-cc1-simple-block.stp", "2e16da42df461a5effa24c7292f46f7bd5b00b31fb4cb44aa608b01d9a078b6c"),
            Map.entry(
                    "annexJ6-cc3-iso14649-11-example1-aim.stp",
                    "4c06283fa180e0da9d0853cfc18c2b659d03eb105d14d947010d9cc0db8c84a6"),
            Map.entry("example2.stp", "5c87b08d50cd8e150649d8c49a444baa73ebee221e309d2badeb64ad876a98af"),
            Map.entry(
                    "iso14649-11-example1-explicit-toolpaths.stp",
                    "3d5129911484e20a38c98dd89e7bc0bfb87b18a6abb6ea0225e048ed2a0e4e0b"),
            Map.entry("iso14649-11-example1.stp", "aa05fe2b9544d8b1f32d97101688b99cbda72d4e9e9d314710bc512fe716a508"),
            Map.entry(
                    "iso14649-11-fdis-example1.p21",
                    "80366f50512c0a38a27b5d99427c3af927d1e67aa5d53858be538da5eaf2e22e"),
            Map.entry(
                    "oneHoleOneSlotOneStepOnePoket.p21",
                    "b9c86ae7c1331a46e87550fee71b4c2caa5d482c9cf71d02a6d4b11f571a4ec4"),
            Map.entry("slots-square-u.stp", "16296703489b57aee04c8a43ff9e122e3d320cac3f8598614abffebc60ba9567"),
            Map.entry("testBoxy.p21", "af592fd1e0d8def8904778ea64defc745dd6481738d29a5d1299f828b8d257f3"),
            Map.entry("testePrecedencias.p21", "1dde8af19bc6b6b076fad01abd624b597501e066f54b7d9f802de940cf18f4c7"));

    static Stream<Path> projectFiles() throws IOException {
        try (Stream<Path> a = Files.list(Path.of("samples/stepnc"));
                Stream<Path> b = Files.list(Path.of("src/test/resources/stepnc"))) {
            return Stream.concat(a.toList().stream(), b.toList().stream())
                    .filter(p -> p.toString().endsWith(".stp"))
                    .sorted();
        }
    }

    static Stream<Path> corpusFiles() throws IOException {
        return StepNcReaderTest.corpusFiles();
    }

    @ParameterizedTest
    @MethodSource("projectFiles")
    void theProjectsFilesGiveTheSameTokensAsBefore(Path file) throws Exception {
        // a test part added since the digests were taken has no "before": it is read whole and
        // one character at a time alike
        sameTokensAsBefore(file, DIGESTS.containsKey(file.getFileName().toString()));
    }

    @ParameterizedTest
    @MethodSource("corpusFiles")
    @CorpusCheck
    void theCorpusFilesGiveTheSameTokensAsBefore(Path file) throws Exception {
        Assumptions.assumeTrue(Files.isRegularFile(file), TestInputs.sharedCorpusAbsent(StepNcReaderTest.CORPUS));
        sameTokensAsBefore(file, true);
    }

    private static void sameTokensAsBefore(Path file, boolean digested) throws Exception {
        String text = Files.readString(file, StandardCharsets.ISO_8859_1);
        String whole = digest(new StringReader(text));
        assertEquals(whole, digest(new Trickle(text)), "one character at a time");
        if (!digested) {
            return;
        }
        String expected = DIGESTS.get(file.getFileName().toString());
        assertTrue(expected != null, "no digest for " + file);
        assertEquals(expected, whole);
    }

    @Test
    void theProjectsDigestedFilesAreStillRead() throws Exception {
        // the project's own files among the digests: if they were renamed away, the test above
        // would compare nothing with the old lexer
        assertTrue(projectFiles()
                        .filter(p -> DIGESTS.containsKey(p.getFileName().toString()))
                        .count()
                >= 7);
    }

    @Test
    void numbersOfEveryShapeReadAsParseDoubleAndParseLongReadThem() throws Exception {
        // signs, leading zeros, 18 digits and more, exponents of every sign, with and without a
        // fraction; whole and one character at a time
        SplittableRandom rnd = new SplittableRandom(21);
        StringBuilder sb = new StringBuilder();
        String[] written = new String[20_000];
        for (int i = 0; i < written.length; i++) {
            String sign = switch (rnd.nextInt(3)) {
                case 0 -> "";
                case 1 -> "-";
                default -> "+";
            };
            String s = sign + "0".repeat(rnd.nextInt(3)) + digits(rnd, rnd.nextInt(1, 19));
            if (rnd.nextBoolean()) {
                s += "." + digits(rnd, rnd.nextInt(0, 26));
                if (rnd.nextBoolean()) {
                    s += (rnd.nextBoolean() ? "E" : "e")
                            + (rnd.nextBoolean() ? "-" : rnd.nextBoolean() ? "+" : "")
                            + rnd.nextInt(0, 280);
                }
            }
            written[i] = s;
            sb.append(s).append(i % 7 == 0 ? ",\n" : ",");
        }
        String text = sb.toString();
        for (Reader in : new Reader[] {new StringReader(text), new Trickle(text)}) {
            Part21Lexer lx = new Part21Lexer(in, "numbers");
            for (String s : written) {
                lx.next();
                boolean real = s.contains(".");
                if (real) {
                    double expected = Double.parseDouble(s);
                    if (Double.isFinite(expected)) {
                        assertEquals(Part21Lexer.Tok.REAL, lx.tok, s);
                        assertEquals(expected, lx.doubleValue, s);
                    }
                } else {
                    assertEquals(Part21Lexer.Tok.INTEGER, lx.tok, s);
                    assertEquals(Long.parseLong(s), lx.longValue, s);
                }
                assertEquals(s, lx.tokenText());
                lx.next();
            }
        }
    }

    private static String digits(SplittableRandom rnd, int n) {
        StringBuilder sb = new StringBuilder(n);
        for (int i = 0; i < n; i++) {
            sb.append((char) ('0' + rnd.nextInt(10)));
        }
        return sb.toString();
    }

    /** The kind, position, text and value of every token, as SHA-256 in hex. */
    static String digest(Reader in) throws IOException, StepParseException, NoSuchAlgorithmException {
        MessageDigest md = MessageDigest.getInstance("SHA-256");
        Part21Lexer lx = new Part21Lexer(in, "digest");
        do {
            lx.next();
            String value = switch (lx.tok) {
                case INTEGER -> Long.toString(lx.longValue);
                case REAL -> Long.toHexString(Double.doubleToRawLongBits(lx.doubleValue));
                default -> "";
            };
            md.update((lx.tok + " " + lx.tokLine + ":" + lx.tokCol + " " + lx.tokenText() + " " + value + "\n")
                    .getBytes(StandardCharsets.UTF_8));
        } while (lx.tok != Part21Lexer.Tok.EOF);
        return HexFormat.of().formatHex(md.digest());
    }

    /** Hands out at most one character per read, so every token straddles a refill of the lexer's buffer. */
    private static final class Trickle extends Reader {
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
}
