package org.fresa.post;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fresa.pocket.DadReader;
import org.fresa.pocket.PassPlanner;
import org.fresa.pocket.PocketPlan;
import org.fresa.pocket.PocketTechnology;
import org.fresa.pocket.Recognition;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class Sinumerik7MPostTest {

    static final Path SAMPLES = Path.of("samples/pocket");

    static PocketPlan plan(String name) throws Exception {
        for (String line : Files.readAllLines(SAMPLES.resolve("jobs.csv"))) {
            String[] f = line.split(",");
            if (f[0].equals(name + ".dad")) {
                PocketTechnology t = new PocketTechnology(d(f[1]), d(f[2]), d(f[3]), d(f[4]), d(f[5]), d(f[6]), d(f[7]),
                        d(f[8]), d(f[9]));
                var profile = DadReader.read(Files.readString(SAMPLES.resolve(f[0])), f[0]);
                return PassPlanner.plan(Recognition.of(profile), t);
            }
        }
        throw new IllegalArgumentException(name);
    }

    private static double d(String s) {
        return Double.parseDouble(s);
    }

    static List<String> lines(String text) {
        return text.lines().map(String::stripTrailing).toList();
    }

    @ParameterizedTest
    @ValueSource(strings = {"examplepart", "cavity01", "cavity02", "cavity03", "cavity04", "cavity05", "cavity06", "cavity07"})
    void compatPostReproducesThePrintedProgram(String name) throws Exception {
        String nc = new Sinumerik7MPost(Sinumerik7MPost.Mode.COMPAT).write(plan(name));
        List<String> golden = lines(Files.readString(SAMPLES.resolve("golden-nc/" + name + ".nc")));
        assertEquals(String.join("\n", golden), String.join("\n", lines(nc)));
    }
}
