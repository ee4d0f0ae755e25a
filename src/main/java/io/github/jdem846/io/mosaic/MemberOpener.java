package io.github.jdem846.io.mosaic;

import io.github.jdem846.io.source.RasterSource;
import java.io.IOException;
import java.nio.file.Path;

/** Opens one file of a mosaic with the reader of its format (the format dispatch of {@code io.DemReader}). */
@FunctionalInterface
public interface MemberOpener {

    /**
     * Opens {@code file}.
     *
     * @param file a DEM file
     * @return the open source
     * @throws IOException naming the file when it cannot be read
     */
    RasterSource open(Path file) throws IOException;
}
