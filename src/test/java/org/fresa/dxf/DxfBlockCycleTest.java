package org.fresa.dxf;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayDeque;
import java.util.Deque;
import org.junit.jupiter.api.Test;

/** A cycle of blocks is named in insertion order, not as one block inserting itself. */
class DxfBlockCycleTest {

    private static String block(String name, String inserts) {
        return "0\nBLOCK\n2\n" + name + "\n10\n0\n20\n0\n0\nLINE\n8\n0\n10\n0\n20\n0\n11\n1\n21\n0\n"
                + "0\nINSERT\n8\n0\n2\n" + inserts + "\n10\n0\n20\n0\n0\nENDBLK\n";
    }

    @Test
    void aCycleOfThreeBlocksIsNamedInTheOrderTheyInsertEachOther() throws Exception {
        String blocks = block("A", "B") + block("B", "C") + block("C", "A");
        DxfDrawing d = DxfReaderTest.read(DxfReaderTest.dxf("", blocks, "0\nINSERT\n8\n0\n2\nA\n10\n0\n20\n0\n"));
        assertAll(
                () -> assertEquals(3, d.curves().size()),
                () -> assertTrue(
                        d.warnings().stream()
                                .anyMatch(w -> w.contains("blocks insert each other in a cycle: A -> B -> C -> A")),
                        d.warnings().toString()));
    }

    @Test
    void theCycleStartsAtTheBlockThatClosesIt() {
        Deque<String> stack = new ArrayDeque<>();
        stack.push("OUTER");
        stack.push("A");
        stack.push("B");
        assertAll(
                () -> assertEquals("blocks insert each other in a cycle: A -> B -> A", DxfReader.cycle(stack, "A")),
                () -> assertEquals("block 'B' inserts itself", DxfReader.cycle(stack, "B")));
    }
}
