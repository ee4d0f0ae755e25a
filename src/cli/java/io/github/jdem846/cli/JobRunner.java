package io.github.jdem846.cli;

import io.github.jdem846.job.OverlaidJob;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.output.ImageOutput;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.overlay.Overlay;
import io.github.jdem846.raster.GridRequestException;
import java.io.PrintWriter;
import java.util.List;
import picocli.CommandLine.Model.CommandSpec;

/**
 * Runs a rendering command's {@link ReliefJob} for a person at a terminal: the output checked against the input
 * first, a progress bar, notices and the sun used on stderr, the phase times with {@code --verbose};
 * {@code --memory} as the job's memory budget (a larger picture is rendered in tiles); an output name without a
 * known image extension, and a window or size that does not fit the grid, reported as bad usage.
 */
final class JobRunner {

    private final CommandSpec spec;
    private final InputOptions input;
    private final OutputOptions output;
    private final ExecutionOptions execution;
    private final VerboseOption verbose;
    private List<Overlay> overlays = List.of();
    private boolean values;

    JobRunner(CommandSpec spec, InputOptions input, OutputOptions output, ExecutionOptions execution,
              VerboseOption verbose) {
        this.spec = spec;
        this.input = input;
        this.output = output;
        this.execution = execution;
        this.verbose = verbose;
    }

    /**
     * @param value vector overlays drawn onto the picture ({@link OverlaidJob}); empty for none
     * @return this runner
     */
    JobRunner withOverlays(List<Overlay> value) {
        overlays = List.copyOf(value);
        return this;
    }

    /**
     * @param value true to write the product's values as float32 ({@link ReliefJob#runAndWriteValues})
     * @return this runner
     */
    JobRunner withValues(boolean value) {
        values = value;
        return this;
    }

    /**
     * Runs {@code job} and writes its product to {@code -o}.
     *
     * @param sunTime the {@code --sun-time} text as given (for the line saying which sun was used), or null
     * @return the exit status, 0
     */
    int run(ReliefJob command, String sunTime) throws Exception {
        ReliefJob job = command.withMemory(execution.memory());
        PrintWriter err = spec.commandLine().getErr();
        PhaseTimes times = new PhaseTimes();
        WriteOptions options = output.writeOptions(execution);
        Usage.check(spec, "--output", () -> ImageOutput.filesWritten(output.path(), options));   // the extension
        job.requireDrawable();
        job.checkOutput(output.path(), options);
        try (ConsoleProgress progress = ConsoleProgress.create(output.quiet, output.progress, err)) {
            ConsoleJobListener listener = new ConsoleJobListener(progress, err, times, sunTime);
            if (values) {
                job.runAndWriteValues(output.path(), options, listener);
            } else if (overlays.isEmpty()) {
                job.runAndWrite(output.path(), options, listener);
            } else {
                new OverlaidJob(job, overlays).runAndWrite(output.path(), options, listener);
            }
        } catch (GridRequestException e) {
            throw input.usageError(e);
        }
        times.print(verbose.isVerbose(), err);
        return 0;
    }
}
