package io.github.jdem846.io.mosaic;

import java.nio.file.Path;
import java.util.List;

/**
 * What a GDAL {@code .vrt} says, as far as this reader follows it: the grid's size, georeferencing and CRS, and
 * band 1's no-data and sources.
 *
 * @param width        {@code rasterXSize}
 * @param height       {@code rasterYSize}
 * @param geoTransform the six {@code GeoTransform} numbers, or {@code null} when absent
 * @param srs          the {@code SRS} text, or {@code null} when absent
 * @param noData       band 1's {@code NoDataValue}, or {@code null}
 * @param bands        how many {@code VRTRasterBand} elements it has
 * @param sources      band 1's sources in document order
 */
record VrtDocument(int width, int height, double[] geoTransform, String srs, Double noData, int bands,
                   List<Source> sources) {

    VrtDocument {
        sources = List.copyOf(sources);
    }

    /**
     * One {@code SimpleSource} or {@code ComplexSource}.
     *
     * @param file   the file, resolved against the VRT's folder when {@code relativeToVRT="1"}
     * @param src    {@code SrcRect} as {xOff, yOff, xSize, ySize}, or {@code null} for the whole file
     * @param dst    {@code DstRect} likewise, or {@code null} for the same as {@code src} at the grid's origin
     * @param noData the source's {@code NODATA}, or {@code null}
     */
    record Source(Path file, int[] src, int[] dst, Double noData) {
    }
}
