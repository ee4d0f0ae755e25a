package io.github.jdem846.io;

/** How elevations are stored in a file (GDAL's names); every type is decoded to float32. */
public enum SampleType {
    INT8("Int8", 1), UINT8("Byte", 1), INT16("Int16", 2), UINT16("UInt16", 2), INT32("Int32", 4),
    UINT32("UInt32", 4), FLOAT32("Float32", 4), FLOAT64("Float64", 8),
    /** Decimal text (ESRI ASCII grid), decoded as float32. */
    TEXT("Text", 0);

    private final String displayName;
    private final int bytes;

    SampleType(String displayName, int bytes) {
        this.displayName = displayName;
        this.bytes = bytes;
    }

    /** GDAL's name of the type, e.g. "Int16", "Float32". */
    public String displayName() {
        return displayName;
    }

    /** Bytes per sample (0 for text). */
    public int bytes() {
        return bytes;
    }
}
