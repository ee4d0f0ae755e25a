package io.github.jdem846.cli;

import io.github.jdem846.geo.LatLonBox;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.output.ImageOutput;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.overlay.Overlay;
import io.github.jdem846.overlay.ProjectedOverlays;
import io.github.jdem846.projection.MapProjection;
import io.github.jdem846.projection.ProjectedExtent;
import io.github.jdem846.projection.ProjectedPicture;
import io.github.jdem846.projection.ProjectedRender;
import io.github.jdem846.raster.GridRequestException;
import io.github.jdem846.render.OutputSize;
import java.io.PrintWriter;
import java.util.List;
import java.util.Optional;
import picocli.CommandLine.Model.CommandSpec;

/**
 * Runs {@code render}, {@code hillshade}, {@code shadows} or {@code skyview} with {@code --projection}: the
 * product on the DEM's grid (one pixel per cell, or fewer for a DEM much larger than the picture: twice the
 * projected picture's width), then warped into the projection and written.
 */
final class ProjectedJobRunner {

    private final CommandSpec spec;
    private final InputOptions input;
    private final OutputOptions output;
    private final ExecutionOptions execution;
    private final VerboseOption verbose;
    private final ProjectionOptions projection;
    private List<Overlay> overlays = List.of();

    ProjectedJobRunner(CommandSpec spec, InputOptions input, OutputOptions output, ExecutionOptions execution,
                       VerboseOption verbose, ProjectionOptions projection) {
        this.spec = spec;
        this.input = input;
        this.output = output;
        this.execution = execution;
        this.verbose = verbose;
        this.projection = projection;
    }

    /**
     * @param value overlays to draw onto the projected picture ({@code --overlay})
     * @return this runner
     */
    ProjectedJobRunner withOverlays(List<Overlay> value) {
        overlays = List.copyOf(value);
        return this;
    }

    /**
     * Runs {@code job} (its size is replaced: --width/--height size the projected picture) and writes it.
     *
     * @param sunTime the {@code --sun-time} text, or null
     * @return the exit status, 0
     */
    int run(ReliefJob command, String sunTime) throws Exception {
        projection.requireConsistent(spec);
        if (input.scale != null) {
            throw Usage.error(spec, "--scale does not apply with --projection: give --width or --height");
        }
        PrintWriter err = spec.commandLine().getErr();
        WriteOptions options = output.writeOptions(execution);
        Usage.check(spec, "--output", () -> ImageOutput.filesWritten(output.path(), options));
        if (command.input() == null) {
            throw Usage.error(spec, "--projection needs a DEM file (the bundled sample is not projected)");
        }
        DemInfo info = DemReader.inspect(command.input());
        Optional<LatLonBox> area = info.geometry().latLonExtent();
        MapProjection map = projection.projection(spec, area);
        try {
            ProjectedExtent.of(info.geometry(), map); // the DEM's CRS and its place on the map, before rendering
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(info.source() + ": " + e.getMessage(), e);
        }
        int width = input.width != null ? input.width : 0;
        int height = input.height != null ? input.height : 0;
        int cols = info.geometry().width();
        int limit = 2 * Math.max(width, height);
        OutputSize shading = command.window() == null && limit > 0 && cols > limit ? OutputSize.width(limit)
                : OutputSize.FULL;
        ReliefJob job = command.withSize(shading).withMemory(execution.memory());
        job.requireDrawable();
        PhaseTimes times = new PhaseTimes();
        try (ConsoleProgress progress = ConsoleProgress.create(output.quiet, output.progress, err)) {
            ConsoleJobListener listener = new ConsoleJobListener(progress, err, times, sunTime);
            ProjectedRender render = new ProjectedRender(map, width, height);
            if (overlays.isEmpty()) {
                render.runAndWrite(job, output.path(), options, listener);
            } else {
                job.checkOutput(output.path(), options);
                ProjectedPicture picture = ProjectedOverlays.paint(render.run(job, listener), overlays);
                picture.write(output.path(), options).notices().forEach(listener::notice);
                listener.phaseDone("write");
            }
        } catch (GridRequestException e) {
            throw input.usageError(e);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(info.source() + ": " + e.getMessage(), e);
        }
        times.print(verbose.isVerbose(), err);
        return 0;
    }
}
