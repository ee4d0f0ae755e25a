package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The launcher's training run: every command in it must run, else the cache would miss that command's classes. */
class AotTrainingTest {

    @Test
    void everyTrainingCommandSucceeds() throws Exception {
        assertEquals(List.of(), AotTraining.train(), "commands of the training run that failed (a renamed option?)");
    }
}
