// End-to-end checks of the model picker (filled in with the model picker).
export async function checkModels() {}
