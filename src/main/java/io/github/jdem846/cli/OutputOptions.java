package io.github.jdem846.cli;

import io.github.jdem846.output.WriteOptions;
import java.nio.file.Path;
import picocli.CommandLine.Option;

/** {@code -o OUT} and {@code --world-file}: where and how the picture is written (atomically). */
public final class OutputOptions {

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "OUT",
            description = "The image to write: .png, or .tif/.tiff for a GeoTIFF. Written to a temporary file "
                    + "first and moved into place, so a failure leaves nothing behind.")
    Path output;

    @Option(names = "--world-file",
            description = "Also write a world file (.pgw/.tfw), a .prj and a GDAL .aux.xml so GIS software "
                    + "places the image (a GeoTIFF carries its georeferencing anyway).")
    boolean worldFile;

    @Option(names = {"-q", "--quiet"}, description = "No progress bar.")
    boolean quiet;

    /** The write options these flags describe; {@code execution} decides whether compression may use all cores. */
    WriteOptions writeOptions(ExecutionOptions execution) {
        return WriteOptions.defaults()
                .withSidecars(worldFile ? WriteOptions.Sidecars.ALWAYS : WriteOptions.Sidecars.NONE)
                .withParallelCompression(execution.threads() > 1);
    }

    /** The output path. */
    Path path() {
        return output;
    }
}
