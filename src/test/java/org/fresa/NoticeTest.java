package org.fresa;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * LICENSE is the GPL 3 and NOTICE names every dependency the jar bundles, with the version Maven
 * resolves (target/runtime-dependencies.txt, written by the dependency plugin before the tests).
 */
class NoticeTest {

    static final Path RESOLVED = Path.of("target/runtime-dependencies.txt");

    /** SHA-256 of the GPL 3 text as the FSF publishes it (gnu.org/licenses/gpl-3.0.txt). */
    static final String GPL3_SHA256 = "3972dc9744f6499f0f9b2dbf76696f2ae7ad8af9b23dde66d6af86c9dfb36986";

    private static final Pattern ENTRY = Pattern.compile("(?m)^([A-Za-z0-9_.-]+:[A-Za-z0-9_.-]+) (\\S+)$");

    @Test
    void theLicenceIsTheGplVersion3AndTheNoticeSaysOrLater() throws Exception {
        byte[] licence = Files.readAllBytes(Path.of("LICENSE"));
        assertEquals(GPL3_SHA256, sha256(licence), "LICENSE is not the unedited GPL 3 text");
        assertTrue(Files.readString(Path.of("NOTICE")).contains("(SPDX: GPL-3.0-or-later)"));
    }

    @Test
    void theNoticeNamesEveryBundledDependencyWithItsVersionAndNothingElse() throws IOException {
        assertTrue(
                Files.isRegularFile(RESOLVED),
                RESOLVED + " is missing: run the tests through Maven (mvn verify), whose"
                        + " dependency plugin writes it");
        Map<String, String> resolved = resolved(Files.readAllLines(RESOLVED));
        Map<String, String> noticed = new TreeMap<>();
        Matcher m = ENTRY.matcher(Files.readString(Path.of("NOTICE")));
        while (m.find()) {
            noticed.put(m.group(1), m.group(2));
        }
        List<String> wrong = new ArrayList<>();
        resolved.forEach((artifact, version) -> {
            if (!version.equals(noticed.get(artifact))) {
                wrong.add("bundled " + artifact + " " + version + ", NOTICE says "
                        + (noticed.containsKey(artifact) ? noticed.get(artifact) : "nothing"));
            }
        });
        noticed.keySet().stream()
                .filter(a -> !resolved.containsKey(a))
                .forEach(a -> wrong.add("NOTICE names " + a + ", which the jar no longer bundles"));
        assertEquals(List.of(), wrong);
        assertTrue(resolved.size() > 50, "Symja alone brings more than 50: " + resolved.keySet());
    }

    @Test
    void theJarCarriesTheLicenceAndTheNoticeInMetaInf() throws IOException {
        for (String name : List.of("LICENSE", "NOTICE")) {
            Path packed = Path.of("target/classes/META-INF", name);
            assertTrue(Files.isRegularFile(packed), packed + " (pom.xml's resources)");
            assertArrayEquals(Files.readAllBytes(Path.of(name)), Files.readAllBytes(packed), name);
        }
    }

    /**
     * groupId:artifactId to version, from {@code mvn dependency:list} output: lines
     * {@code group:artifact:type[:classifier]:version:scope}, perhaps followed by a module name.
     */
    static Map<String, String> resolved(List<String> lines) {
        Map<String, String> out = new TreeMap<>();
        for (String line : lines) {
            if (!line.startsWith("   ") || line.isBlank()) {
                continue;
            }
            String[] c = line.strip().split("\\s+")[0].split(":");
            if (c.length == 5 || c.length == 6) {
                out.put(c[0] + ":" + c[1], c[c.length - 2]);
            }
        }
        return out;
    }

    static String sha256(byte[] data) throws NoSuchAlgorithmException {
        return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(data));
    }
}
