package io.github.jdem846.io;

import io.github.jdem846.io.esri.SidecarCrs;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The files a read of a DEM opens: the data file, and for the ESRI family its {@code .hdr} and {@code .prj} where
 * they exist; for a GDAL {@code .vrt}, the VRT and those of its sources. A writer must replace none of them
 * ({@code io.github.jdem846.output.InputProtection}).
 */
final class InputFiles {

    private InputFiles() {
    }

    /**
     * The existing files a read of {@code file} opens, the data file first ({@code file} itself too when it is a
     * header that stands for its data file).
     *
     * @throws io.github.jdem846.raster.DemFormatException when {@code file} is not a DEM this program reads
     */
    static List<Path> of(Path file) throws java.io.IOException {
        FormatDetector.Detected detected = FormatDetector.detect(file);
        Path data = detected.dataFile();
        List<Path> files = new ArrayList<>();
        files.add(data);
        if (!file.equals(data)) {
            files.add(file);
        }
        switch (detected.format()) {
            case GRIDFLOAT, BIL -> {
                addIfFile(files, SidecarCrs.sibling(data, "hdr"));
                addIfFile(files, SidecarCrs.prjOf(data));
            }
            case ESRI_ASCII -> addIfFile(files, SidecarCrs.prjOf(data));
            case GEOTIFF, SRTM_HGT, MOSAIC -> {
                // self-contained
            }
            case VRT -> {
                for (Path source : io.github.jdem846.io.mosaic.VrtReader.sourceFiles(data)) {
                    for (Path p : of(source)) {
                        if (!files.contains(p)) {
                            files.add(p);
                        }
                    }
                }
            }
        }
        return List.copyOf(files);
    }

    private static void addIfFile(List<Path> files, Path p) {
        if (p != null && Files.isRegularFile(p) && !files.contains(p)) {
            files.add(p);
        }
    }
}
