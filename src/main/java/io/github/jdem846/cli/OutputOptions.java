package io.github.jdem846.cli;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.output.GeoReference;
import io.github.jdem846.output.ImageOutput;
import io.github.jdem846.output.InputProtection;
import io.github.jdem846.output.WriteOptions;
import io.github.jdem846.output.WriteResult;
import io.github.jdem846.raster.GridGeometry;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
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
    WriteOptions options(Double noData, ExecutionOptions execution) {
        WriteOptions o = withSidecars().withParallelCompression(execution.threads() > 1);
        return noData == null ? o : o.withNoData(noData);
    }

    /** The defaults with sidecars as {@code --world-file} says: always, or none. */
    private WriteOptions withSidecars() {
        return WriteOptions.defaults()
                .withSidecars(worldFile ? WriteOptions.Sidecars.ALWAYS : WriteOptions.Sidecars.NONE);
    }

    /**
     * Refuses, before any work, an output that would replace or delete a file of the input DEM (the DEM itself,
     * its {@code .hdr} or {@code .prj}): {@link InputProtection}. Nothing to check for the bundled sample.
     *
     * @throws io.github.jdem846.output.OutputOverwritesInputException naming both files (exit status 2)
     */
    void refuseOverwriting(InputOptions input) throws IOException {
        if (input.file() == null) {
            return;
        }
        List<Path> inputFiles;
        try {
            inputFiles = DemReader.filesOf(input.file());
        } catch (IOException notADem) {
            return;   // the read reports it, with the same message
        }
        InputProtection.check(output, withSidecars(), inputFiles);
    }

    /** Writes RGBA pixels covering {@code geometry}, compressing on as many threads as {@code execution} allows. */
    void writeRgba(int[] argb, GridGeometry geometry, ExecutionOptions execution, PrintWriter err)
            throws IOException {
        WriteResult r = ImageOutput.writeRgba(output, argb, geometry.width(), geometry.height(),
                GeoReference.of(geometry), options(null, execution));
        report(r, err);
    }

    /** Writes a gray image covering {@code geometry}, with {@code noData} (or null) as the GeoTIFF no-data. */
    void writeGray(byte[] gray, GridGeometry geometry, Double noData, ExecutionOptions execution, PrintWriter err)
            throws IOException {
        WriteResult r = ImageOutput.writeGray(output, gray, geometry.width(), geometry.height(),
                GeoReference.of(geometry), options(noData, execution));
        report(r, err);
    }

    private static void report(WriteResult r, PrintWriter err) {
        for (String notice : r.notices()) {
            err.println("jdem846: note: " + notice);
        }
        err.flush();
    }

    /** The output path. */
    Path path() {
        return output;
    }
}
