package org.fresa.app.cli;

import java.util.concurrent.Callable;
import org.fresa.job.Module;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code fresa posts}: the post-processors. */
@Command(name = "posts", mixinStandardHelpOptions = true, description = "List the post-processors.")
final class PostsCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Option(names = "--json", description = "print as JSON")
    boolean json;

    @Override
    public Integer call() {
        return CliSupport.unavailable(spec.commandLine().getErr(), Module.TOOLPATH);
    }
}
