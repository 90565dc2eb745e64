package org.fresa.app.cli;

import java.io.PrintWriter;
import java.util.Map;
import org.fresa.io.Json;
import picocli.CommandLine.Option;

/**
 * A command that lists what the program has built in (robots, post-processors): one JSON object
 * with {@code --json}, else lines for a reader. It reads no input, so it cannot fail.
 */
abstract class ListingCommand extends CliCommand {

    @Option(names = "--json", description = "print as JSON")
    boolean json;

    /** The listing, as the JSON object {@code --json} prints. */
    abstract Map<String, Object> listing();

    /** The listing as lines for a reader. */
    abstract void print(Map<String, Object> listing, PrintWriter out);

    @Override
    public final Integer call() {
        PrintWriter out = out();
        Map<String, Object> listing = listing();
        if (json) {
            out.println(Json.write(listing));
        } else {
            print(listing, out);
        }
        out.flush();
        return CliSupport.EXIT_OK;
    }
}
