package org.fresa.app.cli;

import java.nio.file.Path;
import java.util.List;
import org.fresa.job.StepNcService;
import org.fresa.stepnc.StepNcProgram;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code fresa stepnc FILE [--json]}: describe an ISO 14649 Part 21 file. */
@Command(name = "stepnc", description = "Read an ISO 14649 (STEP-NC) Part 21 file and describe it.")
final class StepncCommand extends CliCommand {

    @Parameters(index = "0", paramLabel = "FILE", description = "Part 21 file (.stp, .p21)")
    Path file;

    @Option(names = "--json", description = "print the description as one JSON object")
    boolean json;

    @Override
    public Integer call() {
        return run(json, progress -> {
            StepNcProgram program = StepNcService.read(file, progress);
            List<StepNcService.NotPlanned> notPlanned = StepNcService.notPlanned(program);
            if (!json) {
                out().print(StepNcService.prose(program));
                out().print(StepNcService.notPlannedProse(notPlanned));
            }
            return StepNcService.describe(program, notPlanned);
        });
    }
}
