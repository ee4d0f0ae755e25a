package io.github.jdem846.io;

/** The DEM file formats {@link DemReader} reads. */
public enum DemFormat {
    /** TIFF with GeoTIFF georeferencing (pixels by TwelveMonkeys imageio-tiff, CRS by Apache SIS). */
    GEOTIFF("GeoTIFF"),
    /** ESRI GridFloat: raw float32 {@code .flt} with an ESRI {@code .hdr} (and optional {@code .prj}). */
    GRIDFLOAT("ESRI GridFloat"),
    /** ESRI ASCII grid ({@code .asc}). */
    ESRI_ASCII("ESRI ASCII grid"),
    /** ESRI band-interleaved-by-line raw raster ({@code .bil} + {@code .hdr}), 16-bit as jDem846 read it. */
    BIL("ESRI BIL"),
    /** SRTM height tile ({@code N34W118.hgt}): big-endian int16, 1″ or 3″, extent from the file name. */
    SRTM_HGT("SRTM HGT"),
    /**
     * Several DEM files read as one grid: tiles of one CRS and cell size on one grid, gaps read as no-data,
     * overlapping cells averaged (docs/formats.md, "Mosaics").
     */
    MOSAIC("mosaic"),
    /**
     * A GDAL virtual raster ({@code .vrt}): an XML file that places tiles of the formats above on one grid, the
     * last source winning where they overlap (docs/formats.md, "Mosaics").
     */
    VRT("GDAL VRT");

    private final String displayName;

    DemFormat(String displayName) {
        this.displayName = displayName;
    }

    /** {@return the name shown to people, e.g. "ESRI GridFloat"} */
    public String displayName() {
        return displayName;
    }
}
