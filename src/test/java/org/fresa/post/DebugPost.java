package org.fresa.post;

import java.nio.file.Files;
import java.nio.file.Path;

class DebugPost {
    public static void main(String[] args) throws Exception {
        for (String a : args) {
            String nc = new Sinumerik7MPost(Sinumerik7MPost.Mode.COMPAT).write(Sinumerik7MPostTest.plan(a));
            Files.writeString(Path.of("/tmp/" + a + ".nc"), nc);
        }
    }
}
