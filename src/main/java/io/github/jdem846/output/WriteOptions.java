package io.github.jdem846.output;

import java.util.Objects;

/**
 * How {@link ImageOutput} writes a file. Immutable; start from {@link #defaults()} and change with the
 * {@code with…} methods.
 *
 * @param sidecars            when to write a world file, a {@code .prj} and a GDAL {@code .aux.xml} next to the image;
 *                            by default never (a GeoTIFF embeds its georeferencing), as the CLI without
 *                            {@code --world-file}
 * @param worldFileNaming     {@code .pgw}/{@code .tfw} or the generic {@code .wld}
 * @param noData              the value marked as no-data in a GeoTIFF (GDAL_NODATA tag), or {@code null} for none;
 *                            for 8-bit products an integer 0..255 (0 for hillshades), for float32 any value or NaN.
 *                            PNG has no no-data marker: RGBA no-data pixels are transparent (alpha 0)
 * @param pngCompressionLevel deflate level 0 (none) to 9 (smallest) for PNG; the default 1 is the fastest level
 *                            and within 10 % of the smallest file (see docs/performance.md)
 * @param parallelCompression compress on all processors: PNG row segments, GeoTIFF strips and COG tiles in the
 *                            common ForkJoinPool (the file is the same either way)
 * @param tiffLayout          how a GeoTIFF is laid out: {@link TiffLayout#STRIPS} (the default) or a
 *                            Cloud-Optimized GeoTIFF ({@link TiffLayout#COG}, GeoTIFF files only)
 * @param cogTileSize         the tile edge of a COG in pixels, a multiple of 16 from 16 to 4096 (default 512)
 * @param jpegQuality         JPEG quality 1 (smallest) to 100 (best), default 90
 * @param background          non-premultiplied 0xAARRGGBB colour an RGBA picture is laid on before writing (no-data
 *                            and partly transparent pixels take it; an opaque colour gives an opaque picture), or
 *                            {@code null} to keep transparency; a JPEG, which has none, uses white when null
 */
public record WriteOptions(Sidecars sidecars, WorldFileNaming worldFileNaming, Double noData,
                           int pngCompressionLevel, boolean parallelCompression, TiffLayout tiffLayout,
                           int cogTileSize, int jpegQuality, Integer background) {

    /** The default JPEG quality. */
    public static final int DEFAULT_JPEG_QUALITY = 90;

    /** The background of a JPEG when none is given: white, as the original's. */
    public static final int DEFAULT_JPEG_BACKGROUND = 0xFFFFFFFF;

    /** The default tile edge of a COG, as GDAL's COG driver. */
    public static final int DEFAULT_COG_TILE_SIZE = 512;

    /** When to write georeferencing sidecar files (world file, .prj, .aux.xml). */
    public enum Sidecars {
        /** Only for formats that cannot hold georeferencing themselves (PNG); a GeoTIFF embeds it. */
        WHEN_NOT_EMBEDDED,
        /** Always, also next to a GeoTIFF (for software that reads only world files). */
        ALWAYS,
        /** Never: the default. */
        NONE
    }

    /** The name of the world file of {@code out.png} or {@code out.tif}. */
    public enum WorldFileNaming {
        /** {@code out.pgw}, {@code out.tfw}: the ESRI convention, first letter + last letter of the extension + w. */
        FORMAT,
        /** {@code out.wld}: the generic name GDAL also reads. */
        WLD
    }

    /** How a GeoTIFF's pixels are laid out in the file. */
    public enum TiffLayout {
        /** Strips of rows (about 64 KiB each), one image: the simplest file, read by every TIFF reader. */
        STRIPS,
        /**
         * A Cloud-Optimized GeoTIFF: 512 × 512 tiles ({@link #cogTileSize()}), overviews each half the size of the
         * one before, and GDAL's COG layout (IFDs first, smallest overview's tiles first), so that a reader can
         * fetch any part at any zoom with a few range requests; {@code gdalinfo} reports {@code LAYOUT=COG}.
         * 8-bit gray and RGBA pictures only.
         */
        COG
    }

    /**
     * Checks that the enumerations are given and the compression level, COG tile size and JPEG quality are in range.
     *
     * @param sidecars when to write a world file, a {@code .prj} and a GDAL {@code .aux.xml} next to the image; by
     *     default never (a GeoTIFF embeds its georeferencing), as the CLI without {@code --world-file}
     * @param worldFileNaming {@code .pgw}/{@code .tfw} or the generic {@code .wld}
     * @param noData the value marked as no-data in a GeoTIFF (GDAL_NODATA tag), or {@code null} for none; for 8-bit
     *     products an integer 0..255 (0 for hillshades), for float32 any value or NaN. PNG has no no-data marker: RGBA
     *     no-data pixels are transparent (alpha 0)
     * @param pngCompressionLevel deflate level 0 (none) to 9 (smallest) for PNG; the default 1 is the fastest level and
     *     within 10 % of the smallest file (see docs/performance.md)
     * @param parallelCompression compress on all processors: PNG row segments, GeoTIFF strips and COG tiles in the
     *     common ForkJoinPool (the file is the same either way)
     * @param tiffLayout how a GeoTIFF is laid out: {@link TiffLayout#STRIPS} (the default) or a Cloud-Optimized GeoTIFF
     *     ({@link TiffLayout#COG}, GeoTIFF files only)
     * @param cogTileSize the tile edge of a COG in pixels, a multiple of 16 from 16 to 4096 (default 512)
     * @param jpegQuality JPEG quality 1 (smallest) to 100 (best), default 90
     * @param background non-premultiplied 0xAARRGGBB colour an RGBA picture is laid on before writing (no-data and
     *     partly transparent pixels take it; an opaque colour gives an opaque picture), or {@code null} to keep
     *     transparency; a JPEG, which has none, uses white when null
     */
    public WriteOptions {
        Objects.requireNonNull(sidecars, "sidecars");
        Objects.requireNonNull(worldFileNaming, "worldFileNaming");
        Objects.requireNonNull(tiffLayout, "tiffLayout");
        if (pngCompressionLevel < 0 || pngCompressionLevel > 9) {
            throw new IllegalArgumentException("PNG compression level must be 0..9, got " + pngCompressionLevel);
        }
        if (cogTileSize < 16 || cogTileSize > 4096 || cogTileSize % 16 != 0) {
            throw new IllegalArgumentException("COG tile size must be a multiple of 16 from 16 to 4096, got "
                    + cogTileSize);
        }
        if (jpegQuality < 1 || jpegQuality > 100) {
            throw new IllegalArgumentException("JPEG quality must be 1..100, got " + jpegQuality);
        }
    }

    /**
     * No sidecars (ask for them with {@link #withSidecars}), {@code .pgw}/{@code .tfw} naming, no no-data tag, PNG
     * level 1, parallel, GeoTIFF strips (COG tiles of 512): the files the CLI writes without {@code --world-file}.
     *
     * @return the default options
     */
    public static WriteOptions defaults() {
        return new WriteOptions(Sidecars.NONE, WorldFileNaming.FORMAT, null, 1, true, TiffLayout.STRIPS,
                DEFAULT_COG_TILE_SIZE, DEFAULT_JPEG_QUALITY, null);
    }

    /**
     * A copy that writes the given sidecars (world file, {@code .prj}, {@code .aux.xml}).
     *
     * @param value which sidecars to write
     * @return a new options record; this one is unchanged
     */
    public WriteOptions withSidecars(Sidecars value) {
        return new WriteOptions(value, worldFileNaming, noData, pngCompressionLevel, parallelCompression, tiffLayout,
                cogTileSize, jpegQuality, background);
    }

    /**
     * A copy that names the world file as given.
     *
     * @param value how the world file is named
     * @return a new options record; this one is unchanged
     */
    public WriteOptions withWorldFileNaming(WorldFileNaming value) {
        return new WriteOptions(sidecars, value, noData, pngCompressionLevel, parallelCompression, tiffLayout,
                cogTileSize, jpegQuality, background);
    }

    /**
     * A copy with the given GeoTIFF no-data value.
     *
     * @param value the value written as the GeoTIFF's no-data tag
     * @return a new options record; this one is unchanged
     */
    public WriteOptions withNoData(double value) {
        return new WriteOptions(sidecars, worldFileNaming, value, pngCompressionLevel, parallelCompression,
                tiffLayout, cogTileSize, jpegQuality, background);
    }

    /**
     * A copy without a GeoTIFF no-data value.
     *
     * @return a new options record; this one is unchanged
     */
    public WriteOptions withoutNoData() {
        return new WriteOptions(sidecars, worldFileNaming, null, pngCompressionLevel, parallelCompression,
                tiffLayout, cogTileSize, jpegQuality, background);
    }

    /**
     * A copy with another PNG deflate level.
     *
     * @param value the level, 0 (none) to 9 (smallest)
     * @return a new options record; this one is unchanged
     */
    public WriteOptions withPngCompressionLevel(int value) {
        return new WriteOptions(sidecars, worldFileNaming, noData, value, parallelCompression, tiffLayout,
                cogTileSize, jpegQuality, background);
    }

    /**
     * A copy that compresses on all processors, or on the calling thread only.
     *
     * @param value true to compress on all processors
     * @return a new options record; this one is unchanged
     */
    public WriteOptions withParallelCompression(boolean value) {
        return new WriteOptions(sidecars, worldFileNaming, noData, pngCompressionLevel, value, tiffLayout,
                cogTileSize, jpegQuality, background);
    }

    /**
     * A copy writing GeoTIFFs in strips or as a Cloud-Optimized GeoTIFF (PNG files refuse the COG layout).
     *
     * @param value strips or COG
     * @return a new options record; this one is unchanged
     */
    public WriteOptions withTiffLayout(TiffLayout value) {
        return new WriteOptions(sidecars, worldFileNaming, noData, pngCompressionLevel, parallelCompression, value,
                cogTileSize, jpegQuality, background);
    }

    /**
     * A copy with COG tiles of {@code value} × {@code value} pixels (a multiple of 16 from 16 to 4096).
     *
     * @param value the tile side in pixels
     * @return a new options record; this one is unchanged
     */
    public WriteOptions withCogTileSize(int value) {
        return new WriteOptions(sidecars, worldFileNaming, noData, pngCompressionLevel, parallelCompression,
                tiffLayout, value, jpegQuality, background);
    }

    /**
     * {@return these options with that JPEG quality}
     *
     * @param value JPEG quality 1..100
     */
    public WriteOptions withJpegQuality(int value) {
        return new WriteOptions(sidecars, worldFileNaming, noData, pngCompressionLevel, parallelCompression,
                tiffLayout, cogTileSize, value, background);
    }

    /**
     * {@return these options with that background}
     *
     * @param argb the colour an RGBA picture is laid on (0xAARRGGBB), or {@code null} to keep transparency
     */
    public WriteOptions withBackground(Integer argb) {
        return new WriteOptions(sidecars, worldFileNaming, noData, pngCompressionLevel, parallelCompression,
                tiffLayout, cogTileSize, jpegQuality, argb);
    }
}
