package org.fresa.io;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fresa.job.TaskOutcome;
import org.junit.jupiter.api.Test;

class JsonTest {

    /** Map.of's order is salted per JVM run; two runs must still write the same summary. */
    @Test
    void anImmutableMapIsWrittenWithItsKeysSorted() {
        assertEquals("{\"a\":1,\"b\":2,\"c\":3,\"d\":4}", Json.write(Map.of("d", 4, "b", 2, "c", 3, "a", 1)));
        assertEquals(
                "[{\"id\":\"WS 1\",\"reason\":\"turning\"}]",
                Json.write(List.of(Map.of("reason", "turning", "id", "WS 1"))));
    }

    @Test
    void anOrderedMapKeepsItsOrder() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("schema", "MACHINING_SCHEMA");
        m.put("workingsteps", 4);
        m.put("planned", 0);
        assertEquals("{\"schema\":\"MACHINING_SCHEMA\",\"workingsteps\":4,\"planned\":0}", Json.write(m));
    }

    /** A task's summary made with Map.of keeps a stable order through the outcome too. */
    @Test
    void anOutcomesSummaryMadeWithMapOfIsInAStableOrder() {
        TaskOutcome o = new TaskOutcome(1, List.of(), Map.of("refused", "x", "out", "p.ngc", "a", 1), List.of());
        assertEquals(List.of("a", "out", "refused"), List.copyOf(o.summary().keySet()));
    }
}
