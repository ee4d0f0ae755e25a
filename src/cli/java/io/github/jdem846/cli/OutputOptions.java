package io.github.jdem846.cli;

import io.github.jdem846.output.ImageOutput;
import io.github.jdem846.output.WriteOptions;
import java.nio.file.Path;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code -o OUT}, {@code --world-file} and {@code --cog}: where and how the picture is written (atomically). */
public final class OutputOptions {

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "OUT",
            description = "The image to write: .png, or .tif/.tiff for a GeoTIFF. Written to a temporary file "
                    + "first and moved into place, so a failure leaves nothing behind.")
    Path output;

    @Option(names = "--world-file",
            description = "Also write a world file (.pgw/.tfw), a .prj and a GDAL .aux.xml so GIS software "
                    + "places the image (a GeoTIFF carries its georeferencing anyway).")
    boolean worldFile;

    @Option(names = "--cog",
            description = "Write the GeoTIFF as a Cloud-Optimized GeoTIFF: 512×512 tiles, Deflate, overviews "
                    + "(gdalinfo reports LAYOUT=COG). Only with a .tif/.tiff output.")
    boolean cog;

    @Option(names = {"-q", "--quiet"}, description = "No progress bar.")
    boolean quiet;

    @Option(names = "--progress", description = "Show progress (read, shadows, shading, write, …) even when "
            + "stderr is not a terminal: a line per update, for logs.")
    boolean progress;

    /** The command these options belong to, for usage errors (null when built by hand). */
    @Spec(Spec.Target.MIXEE)
    CommandSpec mixee;

    /**
     * The write options these flags describe; {@code execution} decides whether compression may use all cores.
     *
     * @throws picocli.CommandLine.ParameterException for {@code --cog} with an output that is not a GeoTIFF
     */
    WriteOptions writeOptions(ExecutionOptions execution) {
        WriteOptions options = WriteOptions.defaults()
                .withSidecars(worldFile ? WriteOptions.Sidecars.ALWAYS : WriteOptions.Sidecars.NONE)
                .withParallelCompression(execution.threads() > 1)
                .withTiffLayout(cog ? WriteOptions.TiffLayout.COG : WriteOptions.TiffLayout.STRIPS);
        if (cog && output != null && mixee != null) {
            Usage.check(mixee, "--cog", () -> ImageOutput.filesWritten(output, options));
        }
        return options;
    }

    /** The output path: {@code -o}, or the one named by {@link #use}; null when neither was. */
    Path path() {
        return output;
    }

    /** Writes to {@code path}, named otherwise than with {@code -o} (gdaldem's positional form). */
    void use(Path path) {
        output = path;
    }
}
