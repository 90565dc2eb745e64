package org.fresa.stepnc;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Random;
import org.fresa.model.CamInputException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Damaged variants of example 2: each is refused with a CamInputException that names a line, and
 * none hangs (the timeout only guards against hangs; it is not a speed requirement).
 */
class DamagedFilesTest {

    private static final Duration HANG_GUARD = Duration.ofSeconds(10);

    static String example2() throws Exception {
        return Files.readString(Path.of("samples/stepnc/example2.stp"), StandardCharsets.UTF_8);
    }

    static CamInputException refused(String text) {
        return assertTimeoutPreemptively(
                HANG_GUARD,
                () -> assertThrows(
                        CamInputException.class,
                        () -> StepNcReader.read(
                                new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), "x.stp")));
    }

    static void assertHasLine(CamInputException e) {
        assertTrue(e.line().isPresent(), e.getMessage());
        assertTrue(e.getMessage().contains("line " + e.line().getAsInt()), e.getMessage());
    }

    @ParameterizedTest
    @ValueSource(doubles = {0.1, 0.5, 0.9, 0.999})
    void aTruncatedFileIsRefusedWithALine(double keep) throws Exception {
        String s = example2();
        CamInputException e = refused(s.substring(0, (int) (s.length() * keep)));
        assertHasLine(e);
    }

    @Test
    void anUnbalancedParenthesisIsRefusedAtItsLine() throws Exception {
        String s = example2().replace("#60=BOTTOM_AND_SIDE_ROUGH_MILLING(", "#60=BOTTOM_AND_SIDE_ROUGH_MILLING((");
        CamInputException e = refused(s);
        assertHasLine(e);
        assertTrue(e.line().getAsInt() >= 1323 - 1262, e.getMessage());
        String t = example2().replace("#4=CARTESIAN_POINT('',(0.0,0.0,0.0));", "#4=CARTESIAN_POINT('',(0.0,0.0,0.0);");
        assertHasLine(refused(t));
    }

    @Test
    void aDanglingReferenceIsRefusedAtTheReferencingLine() throws Exception {
        String s = example2()
                .replace(
                        "#48=MACHINING_WORKINGSTEP('Plane Base Hole_RGH',#15,#35,#25,$);",
                        "#48=MACHINING_WORKINGSTEP('Plane Base Hole_RGH',#15,#35,#9999,$);");
        CamInputException e = refused(s);
        assertHasLine(e);
        assertTrue(e.getMessage().contains("#9999"), e.getMessage());
        assertTrue(e.getMessage().contains("#48"), e.getMessage());
    }

    @Test
    void aDuplicateInstanceNameIsRefusedAtTheSecondDefinition() throws Exception {
        String s = example2().replace("#27=MILLING_CUTTING_TOOL", "#26=MILLING_CUTTING_TOOL");
        CamInputException e = refused(s);
        assertHasLine(e);
        assertTrue(e.getMessage().contains("defined twice"), e.getMessage());
    }

    @Test
    void flippedBytesGiveACamInputExceptionWithALineOrAReadableFile() throws Exception {
        byte[] original = example2().getBytes(StandardCharsets.US_ASCII);
        Random r = new Random(1234);
        int refusedCount = 0;
        for (int trial = 0; trial < 200; trial++) {
            byte[] b = original.clone();
            int at = r.nextInt(b.length);
            b[at] = (byte) (b[at] ^ (1 << r.nextInt(8)));
            if (outcome(b)) {
                refusedCount++;
            }
        }
        assertTrue(refusedCount > 0);
    }

    @Test
    void randomMutationsOfEverySampleOnlyEverSucceedOrGiveACamInputException() throws Exception {
        for (String name :
                new String[] {"example2.stp", "iso14649-11-example1.stp", "iso14649-11-example1-explicit-toolpaths.stp"
                }) {
            byte[] original = Files.readAllBytes(Path.of("samples/stepnc", name));
            for (long seed = 1; seed <= 100; seed++) {
                Random r = new Random(seed);
                byte[] b = mutate(original, r);
                outcome(b);
            }
        }
    }

    /** true when refused; fails the test on anything but success or a located CamInputException. */
    private static boolean outcome(byte[] b) {
        return assertTimeoutPreemptively(HANG_GUARD, () -> {
            try {
                StepNcReader.read(new ByteArrayInputStream(b), "fuzz.stp");
                return false;
            } catch (CamInputException e) {
                assertFalse(e.getMessage().isBlank());
                assertHasLine(e);
                return true;
            }
        });
    }

    private static final String[] INSERTS = {
        "(", ")", ",", ";", "'", "#", "$", "*", ".", "#0", "#99999", "/*", "\\", "\"", "=", "1E400", "-", "#1=",
        "ENDSEC;", "(((", ")))"
    };

    static byte[] mutate(byte[] in, Random r) {
        byte[] b = in.clone();
        int kind = r.nextInt(4);
        int at = r.nextInt(b.length);
        switch (kind) {
            case 0 -> {
                for (int i = 0; i < 1 + r.nextInt(8); i++) {
                    int p = r.nextInt(b.length);
                    b[p] = (byte) r.nextInt(256);
                }
                return b;
            }
            case 1 -> {
                int len = Math.min(b.length - at, 1 + r.nextInt(40));
                byte[] out = new byte[b.length - len];
                System.arraycopy(b, 0, out, 0, at);
                System.arraycopy(b, at + len, out, at, b.length - at - len);
                return out;
            }
            case 2 -> {
                byte[] ins = INSERTS[r.nextInt(INSERTS.length)].getBytes(StandardCharsets.US_ASCII);
                byte[] out = new byte[b.length + ins.length];
                System.arraycopy(b, 0, out, 0, at);
                System.arraycopy(ins, 0, out, at, ins.length);
                System.arraycopy(b, at, out, at + ins.length, b.length - at);
                return out;
            }
            default -> {
                // swap two digits of instance names, making dangling or wrongly typed references
                for (int i = 0; i < 20; i++) {
                    int p = r.nextInt(b.length);
                    if (b[p] >= '0' && b[p] <= '9') {
                        b[p] = (byte) ('0' + r.nextInt(10));
                    }
                }
                return b;
            }
        }
    }
}
