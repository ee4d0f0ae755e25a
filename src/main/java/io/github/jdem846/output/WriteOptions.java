package io.github.jdem846.output;

import java.util.Objects;

/**
 * How {@link ImageOutput} writes a file. Immutable; start from {@link #defaults()} and change with the
 * {@code with…} methods.
 *
 * @param sidecars            when to write a world file, a {@code .prj} and a GDAL {@code .aux.xml} next to the image
 * @param worldFileNaming     {@code .pgw}/{@code .tfw} or the generic {@code .wld}
 * @param noData              the value marked as no-data in a GeoTIFF (GDAL_NODATA tag), or {@code null} for none;
 *                            for 8-bit products an integer 0..255 (0 for hillshades), for float32 any value or NaN.
 *                            PNG has no no-data marker: RGBA no-data pixels are transparent (alpha 0)
 * @param pngCompressionLevel deflate level 0 (none) to 9 (smallest) for PNG; the default 1 is the fastest level
 *                            and within 10 % of the smallest file (see docs/performance.md)
 * @param parallelCompression compress on all processors: PNG row segments and GeoTIFF strips in the common
 *                            ForkJoinPool (the file is the same either way)
 */
public record WriteOptions(Sidecars sidecars, WorldFileNaming worldFileNaming, Double noData,
                           int pngCompressionLevel, boolean parallelCompression) {

    /** When to write georeferencing sidecar files (world file, .prj, .aux.xml). */
    public enum Sidecars {
        /** Only for formats that cannot hold georeferencing themselves (PNG); a GeoTIFF embeds it. */
        WHEN_NOT_EMBEDDED,
        /** Always, also next to a GeoTIFF (for software that reads only world files). */
        ALWAYS,
        /** Never. */
        NONE
    }

    /** The name of the world file of {@code out.png} or {@code out.tif}. */
    public enum WorldFileNaming {
        /** {@code out.pgw}, {@code out.tfw}: the ESRI convention, first letter + last letter of the extension + w. */
        FORMAT,
        /** {@code out.wld}: the generic name GDAL also reads. */
        WLD
    }

    public WriteOptions {
        Objects.requireNonNull(sidecars, "sidecars");
        Objects.requireNonNull(worldFileNaming, "worldFileNaming");
        if (pngCompressionLevel < 0 || pngCompressionLevel > 9) {
            throw new IllegalArgumentException("PNG compression level must be 0..9, got " + pngCompressionLevel);
        }
    }

    /** Sidecars when not embedded, {@code .pgw}/{@code .tfw} naming, no no-data tag, PNG level 1, parallel. */
    public static WriteOptions defaults() {
        return new WriteOptions(Sidecars.WHEN_NOT_EMBEDDED, WorldFileNaming.FORMAT, null, 1, true);
    }

    public WriteOptions withSidecars(Sidecars value) {
        return new WriteOptions(value, worldFileNaming, noData, pngCompressionLevel, parallelCompression);
    }

    public WriteOptions withWorldFileNaming(WorldFileNaming value) {
        return new WriteOptions(sidecars, value, noData, pngCompressionLevel, parallelCompression);
    }

    /** A copy with the given GeoTIFF no-data value. */
    public WriteOptions withNoData(double value) {
        return new WriteOptions(sidecars, worldFileNaming, value, pngCompressionLevel, parallelCompression);
    }

    /** A copy without a GeoTIFF no-data value. */
    public WriteOptions withoutNoData() {
        return new WriteOptions(sidecars, worldFileNaming, null, pngCompressionLevel, parallelCompression);
    }

    public WriteOptions withPngCompressionLevel(int value) {
        return new WriteOptions(sidecars, worldFileNaming, noData, value, parallelCompression);
    }

    /** A copy that compresses on all processors, or on the calling thread only. */
    public WriteOptions withParallelCompression(boolean value) {
        return new WriteOptions(sidecars, worldFileNaming, noData, pngCompressionLevel, value);
    }
}
