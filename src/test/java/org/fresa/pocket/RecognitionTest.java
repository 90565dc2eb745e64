package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

class RecognitionTest {

    static PocketProfile sample(String name) throws Exception {
        Path p = Path.of("../shared/samples/pocket/" + name);
        return DadReader.read(Files.readString(p), name);
    }

    static void dump(RecognitionNode n, String indent) {
        System.out.println(indent + "node " + n.id() + " start " + n.tStart() + " states " + n.states().size());
        for (LoopState s : n.states()) {
            System.out.println(indent + "  t=" + s.tFrom() + " " + s.elements() + " ptr " + s.get(s.pointer()));
        }
        for (RecognitionNode.Event e : n.events()) {
            System.out.println(indent + "  event " + e);
        }
        for (RecognitionNode c : n.children()) {
            dump(c, indent + "    ");
        }
    }

    @Test
    void dumpsAllSamples() throws Exception {
        for (String s : new String[] {"examplepart", "cavity01", "cavity02", "cavity03", "cavity04", "cavity05", "cavity06", "cavity07"}) {
            System.out.println("=== " + s);
            Recognition.Result r;
            try {
                r = Recognition.of(sample(s + ".dad"));
            } catch (Exception e) {
                System.out.println("FAILED " + e);
                continue;
            }
            dump(r.root(), "");
            System.out.println("FURO " + r.maxHoleDiameterMm() + " DMAX " + r.maxToolDiameterMm() + " SUPERF " + r.wallToolDiameterMm());
        }
    }

    @Test
    void cavity01EventsMatchAppendixC() throws Exception {
        Recognition.Result r = Recognition.of(sample("cavity01.dad"));
        RecognitionNode root = r.root();
        assertEquals(7.755355, root.events().get(0).t(), 2e-5);
        assertEquals(15.52132, root.events().get(1).t(), 2e-5);
        assertEquals(17.04619, root.events().get(2).t(), 2e-5);
        assertEquals(18.64534, root.leafT(), 2e-5);
    }
}
