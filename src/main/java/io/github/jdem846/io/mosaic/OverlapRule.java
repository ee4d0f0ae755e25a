package io.github.jdem846.io.mosaic;

/** What a cell covered by several files of a mosaic reads as. */
public enum OverlapRule {
    /**
     * The mean of the files' valid values (jDem846's rule for a list of rasters): summed in double and divided
     * by their count, so equal values, such as the shared edge rows of SRTM tiles, stay exactly what they are.
     */
    MEAN("overlapping cells read as the mean of the files' valid values"),
    /** The value of the last file in the list that has a valid value there (GDAL's rule for a VRT). */
    LAST("overlapping cells read as the last source's valid value (GDAL's rule)");

    private final String description;

    OverlapRule(String description) {
        this.description = description;
    }

    /** @return the rule in words, for a notice */
    public String description() {
        return description;
    }
}
