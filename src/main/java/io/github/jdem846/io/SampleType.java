package io.github.jdem846.io;

/** How elevations are stored in a file (GDAL's names); every type is decoded to float32. */
public enum SampleType {
    /** Signed 8-bit integers. */
    INT8("Int8", 1),
    /** Unsigned 8-bit integers (GDAL's Byte). */
    UINT8("Byte", 1),
    /** Signed 16-bit integers (SRTM, most integer DEMs). */
    INT16("Int16", 2),
    /** Unsigned 16-bit integers. */
    UINT16("UInt16", 2),
    /** Signed 32-bit integers. */
    INT32("Int32", 4),
    /** Unsigned 32-bit integers. */
    UINT32("UInt32", 4),
    /** IEEE 754 single precision. */
    FLOAT32("Float32", 4),
    /** IEEE 754 double precision, rounded to float32. */
    FLOAT64("Float64", 8),
    /** Decimal text (ESRI ASCII grid), decoded as float32. */
    TEXT("Text", 0);

    private final String displayName;
    private final int bytes;

    SampleType(String displayName, int bytes) {
        this.displayName = displayName;
        this.bytes = bytes;
    }

    /** {@return GDAL's name of the type, e.g. "Int16", "Float32"} */
    public String displayName() {
        return displayName;
    }

    /** {@return bytes per sample (0 for text)} */
    public int bytes() {
        return bytes;
    }
}
