package org.fresa.kin;

/**
 * Prints the inverse-kinematics figures (us per point, warm start). Run from the project root:
 * {@code java -cp target/classes:target/test-classes:$(cat cp.txt) org.fresa.kin.IkBenchmarkMain}.
 */
public final class IkBenchmarkMain {
    private IkBenchmarkMain() {}

    public static void main(String[] args) {
        int rounds = args.length > 0 ? Integer.parseInt(args[0]) : 15;
        System.out.println("irb140     " + IkBenchmark.irb140(rounds));
        System.out.println("tricept806 " + IkBenchmark.tricept806(rounds));
    }
}
