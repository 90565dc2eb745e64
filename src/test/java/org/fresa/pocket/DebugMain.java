package org.fresa.pocket;

class DebugMain {
    public static void main(String[] args) throws Exception {
        System.setProperty("pocket.debug", "1");
        for (String a : args) {
            System.err.println("=== " + a);
            try {
                Recognition.of(RecognitionTest.sample(a + ".dad"));
            } catch (Exception e) {
                System.err.println(e);
            }
        }
    }
}
